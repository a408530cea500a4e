// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file label_map_files.h
/// @brief A label map written as the segmentation tools read it: NIfTI-1 (.nii, .nii.gz), NRRD
///        (.nrrd) and 3D Slicer's segmentation (.seg.nrrd: a NRRD carrying each segment's name,
///        colour, label value and extent in its Segment fields).
///
/// Samples are 8-bit when every label fits, else 16-bit, compressed (gzip) except in a .nii. The
/// lattice is written in each format's frame: NIfTI's sform and qform in RAS millimetres (its
/// intent a label map), NRRD's space left-posterior-superior, as Slicer writes them, so the map
/// lies on the scan it was made for in Slicer, ITK-SNAP, FreeSurfer and nibabel.

#include "core/scan/label_map.h"

#include <filesystem>

namespace sculpt {

/// @throws InputError naming the file unless its extension names a format writeLabelMap writes:
/// called before long work so a wrong name fails fast.
void checkLabelMapPath(const std::filesystem::path& path);

/// Writes `map` (atomically) in the format `path`'s extension names.
/// @throws InputError naming the file as checkLabelMapPath, or if it cannot be written.
void writeLabelMap(const LabelMap& map, const std::filesystem::path& path);

}  // namespace sculpt
