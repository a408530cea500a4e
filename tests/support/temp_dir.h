// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file temp_dir.h
/// @brief A fresh directory for one test, removed with everything in it at scope exit.

#include <filesystem>
#include <string>
#include <vector>

namespace sculpt::test {

class TempDir {
public:
    TempDir();
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    const std::filesystem::path& path() const { return mPath; }
    std::filesystem::path operator/(const std::string& name) const { return mPath / name; }
    /// Names of the entries in the directory, sorted.
    std::vector<std::string> entries() const;
    /// Names of the entries in any directory, sorted.
    static std::vector<std::string> entriesOf(const std::filesystem::path& dir);

private:
    std::filesystem::path mPath;
};

}  // namespace sculpt::test
