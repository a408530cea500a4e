// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file private_directory.h
/// @brief A directory only its owner may enter (0700), as the XDG Base Directory specification
///        asks of state directories: recovery copies of unsaved models and the paths a user
///        opened (hospital paths carry patient names) must not be readable on a shared machine.

#include <filesystem>

namespace sculpt {

/// Creates `dir` and its missing parents with mode 0700, whatever the umask, and makes `dir`
/// itself 0700 if it exists with wider permissions. Files written into it through AtomicFile
/// are then 0600. @throws InputError naming the directory if it cannot be made.
void makePrivateDirectory(const std::filesystem::path& dir);

}  // namespace sculpt
