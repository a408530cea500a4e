// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file sdf_rasterizer.h
/// @brief Samples an exact analytic signed distance function into a narrow-band level set.
///
/// Only the leaves (8^3 voxels) that can hold band voxels are visited: a signed distance is
/// 1-Lipschitz, so a leaf whose centre lies farther than (band + half leaf diagonal) from the
/// surface holds no band voxel and is skipped after one evaluation. The interior is then
/// sign-filled (tools::signedFloodFill). Cost: one evaluation per leaf of the bounds plus one
/// per voxel of the band leaves.

#include "core/field/field_image.h"

#include <functional>

namespace sculpt {

/// An analytic shape given by its exact signed distance (world units, negative inside).
struct AnalyticSdf {
    /// Signed distance from a world-space point to the surface.
    std::function<double(const openvdb::Vec3d&)> distance;
    /// World-space box that contains the whole interior.
    openvdb::BBoxd bounds;
    /// Surface area in world units^2, used to estimate memory before allocating.
    double surfaceArea = 0.0;
    /// Name for messages ("sphere of radius 50").
    std::string description;
};

/// Rasterizes `sdf` into a new level set of the given voxel size and band half width.
/// @throws InputError if the voxel size is not positive, the shape is smaller than two voxels
///         across, its index coordinates would overflow, or it would not fit in memory.
FieldImage rasterizeSdf(const AnalyticSdf& sdf, double voxelSize,
                        double halfWidthVoxels = FieldImage::kDefaultHalfWidthVoxels);

}  // namespace sculpt
