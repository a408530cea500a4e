// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file recent_files.h
/// @brief File > Open Recent: the last documents opened or saved, newest first, kept in the
///        state directory (recent.json) across runs.

#include <filesystem>
#include <vector>

namespace sculpt::ui {

class RecentFiles {
public:
    static constexpr std::size_t kMaxEntries = 10;

    /// Loads `stateDir`/recent.json if it exists; a damaged list is ignored.
    explicit RecentFiles(std::filesystem::path stateDir);

    /// Moves `path` to the front and saves the list (a failure to save is ignored: it is a convenience).
    void add(const std::filesystem::path& path);
    const std::vector<std::filesystem::path>& entries() const { return mEntries; }

private:
    std::filesystem::path mFile;
    std::vector<std::filesystem::path> mEntries;
};

}  // namespace sculpt::ui
