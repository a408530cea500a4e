// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file volume_estimate.h
/// @brief Enclosed volume and area of a level set that need not be a signed distance.
///
/// Between redistancings a moving level set drifts from |grad phi| = 1, which biases
/// smeared-delta measures (LevelSetMeasure) by several percent. Here each voxel's value is first
/// divided by its central-difference gradient, phi / |grad phi| being the distance to the surface
/// to first order: the inside fraction of the voxel is clamp(1/2 - d/h, 0, 1) and its share of
/// area a hat function of d. Used by volume control, which needs a consistent measure every step.

#include <openvdb/openvdb.h>

namespace sculpt {

struct VolumeArea {
    double volume = 0.0;  ///< world units^3
    double area = 0.0;    ///< world units^2
};

/// Cost: one parallel pass over the leaves, plus the tiles.
VolumeArea estimateVolumeArea(const openvdb::FloatGrid& grid);

}  // namespace sculpt
