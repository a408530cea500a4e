// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file content_uuid.h
/// @brief Documents whose bytes follow from their content alone.
///
/// OpenVDB writes a fresh random UUID into every file's header (it tells a reader whether a file
/// changed since it read it), so the same document saved twice gave two different files. Batch
/// pipelines want the same input to give the same file bit for bit (whatever the thread count,
/// for caches keyed by content and for checking a rerun), so the writer replaces it with one
/// derived from the rest of the file: equal documents, equal files; different ones, different UUIDs.

#include <filesystem>

namespace sculpt {

/// Replaces the UUID in the header of the .vdb file just written at `file` by a name-based
/// (version 5 layout) UUID hashed from every other byte of the file.
/// @throws InputError naming the file if no UUID sits where OpenVDB writes it.
void stampContentUuid(const std::filesystem::path& file);

}  // namespace sculpt
