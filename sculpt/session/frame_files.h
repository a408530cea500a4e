// SPDX-License-Identifier: Apache-2.0
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

/// Whether file name `a` sorts before `b` as people count: runs of digits by their number
/// (frame_9999 before frame_10000, frame2 before frame10), the rest by character.
bool numberedNameLess(const std::string& a, const std::string& b);

/// The .vdb files of `dir`, in numberedNameLess order. @throws InputError if there are none.
std::vector<std::filesystem::path> documentsIn(const std::filesystem::path& dir);

}  // namespace sculpt
