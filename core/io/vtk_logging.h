// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file vtk_logging.h
/// @brief VTK's logger kept off stderr, for programs (VTK-free header: the command line's main
///        includes it).

namespace sculpt {

/// Keeps VTK's logger off stderr (each program's main calls it once): VTK's errors reach the
/// user through VtkErrorCatcher (vtk_error_catcher.h), as one line naming the file.
void quietVtkLogger();

}  // namespace sculpt
