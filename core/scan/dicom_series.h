#pragma once
/// @file dicom_series.h
/// @brief A directory of DICOM slices assembled into one scan.
///
/// Each slice is read by VTK's vtkDICOMImageReader (uncompressed transfer syntaxes only) with its
/// patient position and orientation; the slices are sorted along the slice normal and must agree
/// in size, orientation and sample type and be evenly spaced (a gap is a missing slice).

#include "core/scan/scan_volume.h"

#include <filesystem>

namespace sculpt {

/// @throws InputError naming the directory or slice: fewer than two slices, a file that is not
///         an image slice, mixed series, two slices at one position, uneven spacing.
ScanVolume readDicomSeries(const std::filesystem::path& dir);

}  // namespace sculpt
