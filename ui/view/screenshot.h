// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file screenshot.h
/// @brief The composed frame (the 3D view and the panels over it) read back from the OpenGL
///        context's back buffer and written as a PNG.

#include <filesystem>

namespace sculpt::ui {

/// Writes the back buffer's `width` x `height` pixels to `path`. @return false if it could not.
bool writeScreenshot(const std::filesystem::path& path, int width, int height);

}  // namespace sculpt::ui
