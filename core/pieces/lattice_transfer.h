// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file lattice_transfer.h
/// @brief One piece's field on another's voxels: what merging and pushing two pieces need, since
///        each piece keeps its own voxel size and placement.

#include "core/field/field_image.h"

namespace sculpt {

/// `source`'s surface, placed by `sourcePlacement`, as a level set on `target`'s lattice as
/// `targetPlacement` places it, with a band of `halfWidthVoxels` (target voxels) either side.
/// The source itself when both lattices and placements agree and the band is the source's; its
/// voxels shifted, exactly, when the placements differ by whole voxels; else rebuilt (OpenVDB's
/// levelSetRebuild: a ball 12 voxels across loses about 0.7% of its volume).
FieldImage onLatticeOf(const FieldImage& source, const openvdb::Mat4d& sourcePlacement, const FieldImage& target,
                       const openvdb::Mat4d& targetPlacement, double halfWidthVoxels);

}  // namespace sculpt
