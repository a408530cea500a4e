// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file kept_scan.h
/// @brief The scan a document was imported from, kept in the document: its samples as a float
///        grid of their own, on the scan's own lattice, so the window can show its slices and the
///        surface can be imported again at another iso-value without the original file.
///
/// The grid ("scan") maps its index space to the document's world (LPS millimetres) by the scan's
/// own affine map: voxel (i, j, k) is sample (i, j, k). It is sparse where the scan is uniform:
/// the background is the smallest sample (the air of a CT, the zero outside an MRI's head), held
/// by no voxel, and uniform 8^3 blocks become tiles. Integer samples of at most 2048 in magnitude
/// (8-bit scans, most MRIs) are written as half floats, which hold them exactly. Its metadata:
///   sculpt.scan_dims    (vec3i)  — the scan's samples along i, j, k
///   sculpt.scan_source  (string) — the file or directory it was read from (its name)
///   sculpt.scan_type    (string) — the samples' type in that file ("unsigned char", "short", ...)
///   sculpt.scan_iso     (double) — the iso-value the document's surface was imported at, if any
///   sculpt.checksum     (string) — gridChecksum() of its voxels

#include "core/scan/scan_lattice.h"
#include "core/scan/scan_volume.h"

#include <openvdb/openvdb.h>

#include <filesystem>
#include <optional>
#include <string>

namespace sculpt {

/// The name a kept scan's grid is written under.
inline constexpr const char* kKeptScanName = "scan";

/// The scan as a grid to keep with the document imported from it at `iso` (none: a label map's
/// pieces).
openvdb::FloatGrid::Ptr keptScanGrid(const ScanVolume& scan, std::optional<double> iso);

/// Whether a grid of a document is a kept scan (a float grid carrying sculpt.scan_dims).
bool isKeptScan(const openvdb::GridBase& grid);

/// The kept scan among a document's other grids, or nullptr.
openvdb::FloatGrid::ConstPtr findKeptScan(const openvdb::GridPtrVec& grids);

/// What a kept scan records of itself, checked.
struct KeptScanRecord {
    ScanLattice lattice;
    std::string source, sampleType;
    std::optional<double> iso;
};
/// @throws InputError (not naming the file: the caller does) if a field is missing or cannot be:
///         dimensions not positive or beyond a scan's, a map that is not affine, not finite or
///         flattens the lattice, voxels outside the dimensions, a checksum that does not match.
KeptScanRecord keptScanRecord(const openvdb::FloatGrid& grid);

/// The kept scan's samples as a scan again (a dense copy in floats), placed as it was.
/// @throws InputError naming `source` as keptScanRecord, or if the copy would not fit in memory.
ScanVolume scanOfKept(const openvdb::FloatGrid& grid, const std::string& source);

/// The scan kept in the document at `path`.
/// @throws InputError naming the file if it is not a readable document or keeps no scan.
ScanVolume readKeptScan(const std::filesystem::path& path);

}  // namespace sculpt
