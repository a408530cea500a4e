#pragma once
/// @file label_names.h
/// @brief The names and colours a segmentation tool keeps beside a label map, for its pieces:
///        MRIcron's (and FSLeyes') "<volume>.txt", a line "value name ..." per label, and
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

/// The looks of the labels the files beside `volume` give ("atlas.nii.gz" -> "atlas.nii.txt" and
/// "atlas.nii.lut"; "seg.nrrd" -> "seg.txt", "seg.lut"). Files that are missing give nothing; a
/// line that names no label is skipped, and a file that cannot be read adds a warning.
std::map<int, LabelLook> readLabelLooks(const std::filesystem::path& volume, std::vector<std::string>& warnings);

}  // namespace sculpt
