// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file sample_files.h
/// @brief Where a detached header's samples are: one data file, or a list of them (NRRD's
///        `data file: LIST` and `data file: slice%03d.raw 1 120 1`, MetaImage's
///        `ElementDataFile = LIST` and `= slice%03d.raw 1 120 1`), and zlib data that must
///        inflate to exactly what the header declares. Internal to scan/ (header_checks.h).

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace sculpt {

/// Files one header may list: a slice per file for the tallest CT stacks.
constexpr std::size_t kMaxDataFiles = 65536;

/// The files a data-file field names, relative to `dir`: `spec` itself, a printf-style pattern
/// with its first, last and step (one %d, %0Nd or %Nd conversion, nothing else), or LIST with
/// the names in `listLines`; each must exist.
/// @throws InputError (`where` + what) for a bad pattern or range, more than `maxFiles` files
///         (never more than kMaxDataFiles), or a missing file.
std::vector<std::filesystem::path> dataFiles(const std::string& spec, const std::vector<std::string>& listLines,
                                             const std::filesystem::path& dir, double maxFiles,
                                             const std::string& where);

/// Bytes the files hold together, less `skip` bytes at the start of the first.
double bytesIn(const std::vector<std::filesystem::path>& files, double skip);

/// Inflates the zlib or gzip data starting `offset` bytes into `file` and refuses it unless it
/// is whole and inflates to exactly `expected` bytes (never inflating much beyond that).
/// @throws InputError (`where` + what).
void requireInflatesTo(const std::filesystem::path& file, std::uint64_t offset, double expected,
                       const std::string& where);

}  // namespace sculpt
