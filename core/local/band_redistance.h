// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file band_redistance.h
/// @brief Local redistancing of a narrow band after an edit moved it by up to a voxel.
///
/// What openvdb::tools::LevelSetTracker::track does (dilate the band one voxel, one
/// normalisation iteration, trim), but only for the voxels inside a capsule and on a dense copy
/// of its box: the tracker visits every leaf of the grid and rebuilds aux buffers for them, which
/// made it 80% of a brush stamp. Steps, each reading the previous one's values:
///   1. one first-order Godunov iteration of dphi/dtau = S(phi)(1 - |grad phi|), dtau = 0.3 h,
///      S(phi) = phi / sqrt(phi^2 + h^2), on the band's voxels (as the tracker's normaliser);
///   2. voxels beyond the band next to it get the first-order Eikonal value from their band
///      neighbours (exact for planes, where the tracker's dilation starts from the background);
///   3. |phi| >= background becomes inactive +-background, the rest active.

#include "core/local/capsule.h"

#include <openvdb/openvdb.h>

namespace sculpt {

/// Redistances the band of `grid` (a level set) inside `zone`; voxels outside keep their values.
/// Deterministic. Cost: the voxels of the zone's box.
void redistanceBand(openvdb::FloatGrid& grid, const Capsule& zone);

}  // namespace sculpt
