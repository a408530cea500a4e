#pragma once
/// @file frame_files.h
/// @brief Numbered frames in a directory (DIR/frame_0000.vdb ...), as morph writes them and
///        render reads and writes them.

#include <filesystem>
#include <string>
#include <vector>

namespace sculpt {

/// DIR/frame_NNNN.EXT
std::filesystem::path framePath(const std::filesystem::path& dir, int index, const std::string& extension);

/// The .vdb files of `dir`, sorted by name. @throws InputError if there are none.
std::vector<std::filesystem::path> documentsIn(const std::filesystem::path& dir);

}  // namespace sculpt
