// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file metadata_seal.h
/// @brief The seal over the metadata a document says about itself (every `sculpt.*` field of the
///        file and of each of its grids: units, frame, placements, colours, labels, a kept scan's
///        dimensions...): a hash of each field, written beside them as `sculpt.sealed`, so that a
///        field edited or damaged after it was written is caught on read, and named.
///
/// The voxels have their own checksum (`sculpt.checksum`, grid_checksum.h); the seal covers the
/// fields, that checksum included. A file without a seal (another program's, or ours from before
/// the seal) is read as it is, each field still checked for what it may be.

#include <openvdb/openvdb.h>

#include <string>

namespace sculpt {

/// The metadata field holding the seal.
inline constexpr const char* kMetadataSealKey = "sculpt.sealed";

/// Seals the `sculpt.*` fields of `meta` (a file's metadata, or a grid's) as they are now.
void sealMetadata(openvdb::MetaMap& meta);

/// @throws InputError (saying `whose`, e.g. "piece 'skull'") naming the first `sculpt.*` field
///         that was changed, added or removed since `meta` was sealed. Nothing if it holds no seal.
void checkMetadataSeal(const openvdb::MetaMap& meta, const std::string& whose);

}  // namespace sculpt
