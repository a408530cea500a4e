#pragma once
/// @file scan_to_level_set.h
/// @brief A scan's iso-surface as an editable field image.
///
/// The scan is resampled (trilinear, in its own index space, so spacing, orientation and origin
/// are honoured) onto an axis-aligned world grid of the chosen voxel size, one slab of 8 output
/// layers at a time. Only the voxels next to a crossing of the iso-value keep iso - f in a sparse
/// grid; a signed flood fill gives every other voxel its side, the band is dilated around those
/// seeds, and openvdb::tools::sdfToSdf computes its distances by fast sweeping from the crossings
/// (fogToSdf would take the band's inactive inside for outside and see a false surface at the
/// band's edge). Peak memory: the scan, the few slices a slab reads, and the band. Inside is
/// where samples exceed the iso value (bright tissue on CT and T1 MRI); the scan's outside counts
/// as outside, so surfaces cut by the scan's border are capped there.

#include "field_image.h"
#include "progress.h"
#include "scan_volume.h"

namespace sculpt {

/// @param voxelSizeWorld edge of the output voxels; the scan's smallest spacing is its native size.
/// @throws InputError if the iso-value is outside the samples' range or nothing is inside,
///         or the output would not fit in memory; Cancelled if progress says stop.
FieldImage scanToLevelSet(const ScanVolume& scan, double iso, double voxelSizeWorld, const Progress& progress = {});

/// The smallest distance between neighbouring samples: the scan's native voxel size.
double nativeVoxelSize(const ScanVolume& scan);

/// Keeps only the connected piece with the largest surface (scans are full of islands).
/// @return the number of pieces dropped.
std::size_t keepLargestComponent(FieldImage& field);

} // namespace sculpt
