// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file disk_budget.h
/// @brief Refuse a long write (a sequence of frames) the disk cannot hold, before it fills it.

#include <filesystem>
#include <string>

namespace sculpt {

/// @throws InputError naming `dir` and `what` if `bytes` exceed the space free to us on the
///         file system that holds `dir`.
void requireDiskSpace(double bytes, const std::filesystem::path& dir, const std::string& what);

}  // namespace sculpt
