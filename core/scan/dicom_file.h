// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file dicom_file.h
/// @brief One DICOM file's image as GDCM decodes it, with each frame's place in the patient.
///
/// GDCM reads every transfer syntax archives use (uncompressed, RLE, JPEG lossless and lossy,
/// JPEG-LS, JPEG 2000) and both classic single-frame slices and enhanced multi-frame files.
/// Internal to scan/: the series reader (dicom_series.h) assembles these into a scan.

#include <openvdb/openvdb.h>
#include <vtkImageData.h>
#include <vtkSmartPointer.h>

#include <filesystem>
#include <string>
#include <vector>

namespace sculpt {

struct DicomFrames {
    /// Columns x rows x frames, in the file's order (row 0 is the first row the file stores), in
    /// modality units: stored values through the rescale slope and intercept (float if those
    /// change anything, else the stored type).
    vtkSmartPointer<vtkImageData> samples;
    std::vector<openvdb::Vec3d> positions;  ///< (0020,0032) of each frame's first pixel
    openvdb::Vec3d rowDirection, columnDirection;
    double columnSpacing = 1.0;  ///< between neighbouring columns: along a row
    double rowSpacing = 1.0;     ///< between neighbouring rows: down a column
    std::string seriesUid;       ///< (0020,000E), empty if the file has none
    std::string file;
};

/// @throws InputError naming the file: not DICOM, not a greyscale image, no orientation or
///         position, pixel data that cannot be decoded or is shorter than the image.
DicomFrames readDicomFile(const std::filesystem::path& file);

}  // namespace sculpt
