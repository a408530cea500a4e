// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file dicom_writer.h
/// @brief Writes minimal DICOM images (explicit VR little endian, 16-bit monochrome) so tests can
///        build series with known geometry: classic slices, or one enhanced multi-frame file.

#include <openvdb/openvdb.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace sculpt::test {

struct DicomSliceSpec {
    int rows = 0, columns = 0;
    double rowSpacing = 1.0, columnSpacing = 1.0, sliceThickness = 1.0;
    openvdb::Vec3d position{0.0};                   ///< (0020,0032) of the first pixel
    openvdb::Vec3d rowDirection{1.0, 0.0, 0.0};     ///< along a row (increasing column)
    openvdb::Vec3d columnDirection{0.0, 1.0, 0.0};  ///< down a column (increasing row)
    int instanceNumber = 1;
    std::string seriesUid = "1.2.3.4.5";
    std::vector<std::uint16_t> pixels;  ///< rows x columns, row by row
};

void writeDicomSlice(const std::filesystem::path& path, const DicomSliceSpec& slice);
/// The frames (one size, orientation and spacing) in one file, each frame at its own position.
void writeDicomMultiFrame(const std::filesystem::path& path, const std::vector<DicomSliceSpec>& frames);

/// A DICOMDIR listing `images` (paths relative to its directory, components separated by
/// backslashes, as discs write them) as IMAGE records under a patient, study and series.
void writeDicomdir(const std::filesystem::path& path, const std::vector<std::string>& images);

}  // namespace sculpt::test
