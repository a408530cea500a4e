// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file file_bytes.h
/// @brief A file's bytes as one string and back: what tests that damage files work on.

#include <filesystem>
#include <string>

namespace sculpt::test {

/// The whole file; empty when it cannot be read.
std::string fileBytes(const std::filesystem::path& path);

/// Replaces the file with exactly these bytes.
void writeFileBytes(const std::filesystem::path& path, const std::string& bytes);

}  // namespace sculpt::test
