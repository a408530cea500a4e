// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file file_extension.h
/// @brief How file formats are recognised: by a path's lower-case extension.

#include <filesystem>
#include <string>

namespace sculpt {

/// The extension in lower case (".PLY" -> ".ply"), with ".gz" joined to the one before it
/// ("brain.nii.gz" -> ".nii.gz").
std::string lowerExtension(const std::filesystem::path& path);

}  // namespace sculpt
