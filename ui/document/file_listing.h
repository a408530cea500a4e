// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file file_listing.h
/// @brief What a file prompt shows under its path field: one directory's folders and the files
///        of the kinds the prompt accepts, with size and date, and Tab completion of a typed path.
///        No ImGui here: the file chooser panel draws it, tests read it.

#include <cstdint>
#include <ctime>
#include <filesystem>
#include <string>
#include <vector>

namespace sculpt::ui {

/// The files a prompt accepts.
struct FileKinds {
    std::vector<std::string> extensions;  ///< lower case, ".nii.gz" whole; empty: every file
    bool extensionless = false;           ///< files without an extension too (DICOM slices often have none)
    bool folderAnswers = false;           ///< a folder is an answer (a DICOM series, a directory for frames)

    bool acceptsFile(const std::filesystem::path& path) const;
};

struct FileEntry {
    std::string name;
    bool folder = false;
    std::uintmax_t bytes = 0;  ///< files only
    std::time_t modified = 0;
};

struct DirectoryListing {
    std::filesystem::path directory;
    std::vector<FileEntry> entries;  ///< folders first, then files, each by name
    bool truncated = false;          ///< the directory held more than the limit
    std::string error;               ///< why it could not be read, or ""
};

/// The folders and accepted files of `directory`, hidden ones (".name") left out, at most `limit`
/// of them however large the directory (a folder of a million slices must not stall the window).
DirectoryListing listDirectory(const std::filesystem::path& directory, const FileKinds& kinds,
                               std::size_t limit = 4000);

/// "~/x" as $HOME/x; any other text as it is.
std::filesystem::path expandHome(const std::string& typed);

/// The directory a typed path shows: the path itself if it is a directory (or ends in "/"), else
/// its parent; the current directory for a bare name.
std::filesystem::path directoryOf(const std::string& typed);

/// Tab: `typed` extended by the longest prefix shared by the names in its directory (folders and
/// accepted files) that start with its last part; a lone folder gets its "/". Else unchanged.
std::string completePath(const std::string& typed, const FileKinds& kinds);

}  // namespace sculpt::ui
