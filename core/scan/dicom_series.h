// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file dicom_series.h
/// @brief A DICOM series (a directory of slices, or one multi-frame file) assembled into one scan.
///
/// Files are decoded by GDCM (dicom_file.h). The slices are sorted along the slice normal and
/// must agree in series, size and orientation. Scanners round slice positions, so real series
/// are not evenly spaced: an uneven series is resampled to even spacing with every slice at its
/// own position (and a warning); a step of 1.5 times the usual or more is a missing slice.

#include "core/scan/scan_volume.h"

#include <filesystem>

namespace sculpt {

/// A directory: every slice in it, all of one series. A file: its frames if it holds several
/// (enhanced multi-frame), else the series in its directory that the slice belongs to.
/// @throws InputError naming the directory or file: fewer than two slices, a file that is not an
///         image slice, several series, mixed sizes or orientations, two slices at one position,
///         a missing slice.
ScanVolume readDicomSeries(const std::filesystem::path& path);

/// True for the extensions DICOM files carry (.dcm, .dicom, .ima), in any case.
bool isDicomFile(const std::filesystem::path& path);

}  // namespace sculpt
