// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file label_names.h
/// @brief The names and colours a segmentation tool gives a label map's values, for its pieces:
///        3D Slicer's in a segmentation's NRRD header ("Segment0_Name:=Liver",
///        "Segment0_LabelValue:=1", "Segment0_Color:=0.9 0.5 0.4"), MRIcron's (and FSLeyes')
///        beside the volume: "<volume>.txt", a line "value name ..." per label, and
///        "<volume>.lut", 768 bytes: 256 reds, then 256 greens, then 256 blues.

#include <openvdb/openvdb.h>

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace sculpt {

struct LabelLook {
    std::string name;                      ///< empty: none given
    std::optional<openvdb::Vec3f> colour;  ///< sRGB 0..1
};

/// The looks of the labels a NRRD volume's header or the files beside `volume` give ("atlas.nii.gz" -> "atlas.nii.txt" and
/// "atlas.nii.lut"; "seg.nrrd" -> "seg.txt", "seg.lut"). Files that are missing give nothing; a
/// line that names no label is skipped, and a file that cannot be read adds a warning.
std::map<int, LabelLook> readLabelLooks(const std::filesystem::path& volume, std::vector<std::string>& warnings);

}  // namespace sculpt
