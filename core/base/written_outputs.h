// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file written_outputs.h
/// @brief What a long write makes (a morph's frames, a tracked sequence, a sequence's renders,
///        the meshes of several pieces), taken back if it fails before the end: a failed command
///        leaves no partial output beside the user's files. Each file is still written
///        atomically (atomic_file.h); files that were there before and directories this did not
///        make are never removed.

#include <filesystem>
#include <string>
#include <vector>

namespace sculpt {

class WrittenOutputs {
public:
    WrittenOutputs() = default;
    /// Unless kept: removes the files it noted, then the directories it made (if empty).
    ~WrittenOutputs();
    WrittenOutputs(const WrittenOutputs&) = delete;
    WrittenOutputs& operator=(const WrittenOutputs&) = delete;

    /// Makes `dir` if it does not exist (removed again on failure).
    /// @throws InputError if its parent does not exist or it cannot be made.
    void directory(const std::filesystem::path& dir);
    /// `path` is about to be written: removed on failure (unless it was there before).
    /// @return `path`, to write to.
    const std::filesystem::path& file(const std::filesystem::path& path);
    /// Once the first of a sequence's items is written (every file noted so far): refuses if
    /// `others` more, each `scale` times as large, would not fit where they go.
    /// @throws InputError naming the directory and `what` (disk_budget.h).
    void requireRoomFor(long long others, double scale, const std::string& what) const;
    /// The work succeeded: everything stays.
    void keep() { mKept = true; }

private:
    std::vector<std::filesystem::path> mFiles, mDirectories;
    bool mKept = false;
};

}  // namespace sculpt
