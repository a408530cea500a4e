// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file scan_to_level_set.h
/// @brief A scan's iso-surface as an editable field image.
///
/// The output lattice (axis-aligned, the chosen voxel size) is cut into tiles of 32 x 32 x 16
/// voxels, converted in parallel and independently: a tile whose scan samples all lie on one side
/// of the iso-value (known from the samples' range per 8^3 block) is skipped; the others are
/// resampled with a 5-voxel margin (trilinear, in the scan's own index space, so spacing,
/// orientation and origin are honoured), the voxels next to a crossing get their distance to it,
/// fast marching carries distances out to the band's width, and the leaves the band touches go
/// into the grid. A signed flood fill then gives the untouched inside its sign. Peak memory: the
/// scan, the band, and a few hundred KiB per thread. Inside is where samples exceed the iso-value
/// (bright tissue on CT and T1 MRI); the scan's outside counts as outside, so surfaces cut by the
/// scan's border are capped there.

#include "core/base/progress.h"
#include "core/field/field_image.h"
#include "core/scan/scan_volume.h"

namespace sculpt {

/// @param voxelSizeWorld edge of the output voxels; the scan's smallest spacing is its native size.
/// @throws InputError if the iso-value is outside the samples' range or nothing is inside,
///         or the output would not fit in memory; Cancelled if progress says stop.
FieldImage scanToLevelSet(const ScanVolume& scan, double iso, double voxelSizeWorld, const Progress& progress = {});

/// The scan's native voxel size: the smallest distance between neighbouring samples, but no
/// finer than a sixteenth of the largest (a slab-thin axis would multiply the work by its ratio
/// cubed for nothing the other axes hold).
double nativeVoxelSize(const ScanVolume& scan);

}  // namespace sculpt
