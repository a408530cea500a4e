// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file scan_readers.h
/// @brief Reading a scan from its file(s) into a ScanVolume.
///
/// Readers are VTK's for NIfTI (.nii, .nii.gz, with its sform or else qform), NRRD (.nrrd, .nhdr)
/// and MetaImage (.mha, .mhd), ours for INRIMAGE (.inr, .inr.gz: inrimage_file.h), GDCM's for DICOM (a directory of slices, one slice of a series,
/// or a multi-frame file: dicom_series.h), and ours for raw samples with a layout given by the
/// user. Every reader checks what the header claims against
/// sane limits and the memory available before the samples are allocated (header_checks.h,
/// here); the third-party library then decodes in a child process (isolated_call.h), so that
/// its abort, crash or runaway allocation is one InputError naming the file, never the end of
/// the program and its document.

#include "core/scan/scan_volume.h"

#include <filesystem>
#include <string>

namespace sculpt {

/// How the samples of a headerless raw file are laid out.
struct RawLayout {
    openvdb::Coord dims{0, 0, 0};  ///< samples along x (fastest), y, z
    std::string type = "uint8";    ///< uint8, int8, uint16, int16, uint32, int32, float32, float64
    openvdb::Vec3d spacing{1.0};   ///< voxel size along x, y, z (world units)
    openvdb::Vec3d origin{0.0};    ///< world position of sample (0, 0, 0)
    bool bigEndian = false;
    std::size_t headerBytes = 0;  ///< bytes to skip at the start of the file
};

/// Reads a scan by its extension (.nii, .nii.gz, .nrrd, .nhdr, .mha, .mhd, .inr, .inr.gz; .dcm,
/// .dicom, .ima), a document's kept scan (.vdb: kept_scan.h) or, for a directory, as a DICOM series.
/// @throws InputError naming the file and the problem: unknown format, unreadable, truncated
///         or corrupt, absurd dimensions (refused before allocating), a DICOM directory with
///         several series, mixed sizes or missing slices.
ScanVolume readScan(const std::filesystem::path& path);
/// Reads headerless samples. @throws InputError as readScan, or if the file is shorter than
/// the layout says.
ScanVolume readRawScan(const std::filesystem::path& path, const RawLayout& layout);

/// True if readScan knows the path's extension (or it is a directory).
bool isScanPath(const std::filesystem::path& path);

}  // namespace sculpt
