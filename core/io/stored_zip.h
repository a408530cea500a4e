// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file stored_zip.h
/// @brief A ZIP archive of stored (uncompressed) entries: the container of 3MF files. Entries
///        carry a fixed date, so equal contents give equal archives.

#include <filesystem>
#include <string>
#include <vector>

namespace sculpt {

struct ZipEntry {
    std::string name;   ///< its path in the archive, '/'-separated
    std::string bytes;  ///< its content
};

/// Writes `entries` as a ZIP archive to `path` (not atomically: callers write a temporary).
/// @throws InputError naming `path` if the archive would pass 4 GiB (ZIP64 is not written) or
///         the write fails.
void writeStoredZip(const std::vector<ZipEntry>& entries, const std::filesystem::path& path);

}  // namespace sculpt
