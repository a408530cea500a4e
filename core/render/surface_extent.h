// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file surface_extent.h
/// @brief Where a surface may be, for framing it in a camera: the world bounding box of its band
///        and the centres of the band's leaves. Fields add up, so a sequence of morph frames
///        gets one extent that covers them all.

#include "core/field/field_image.h"

#include <vector>

namespace sculpt {

struct SurfaceExtent {
    openvdb::BBoxd bounds;                    ///< world box of the band's active voxels (empty: none)
    std::vector<openvdb::Vec3d> leafCentres;  ///< world centres of the band's leaves
    double padWorld = 0.0;                    ///< every voxel of a leaf lies within this of its centre

    SurfaceExtent() = default;
    explicit SurfaceExtent(const FieldImage& field) { add(field); }
    /// Grows the extent by `field`'s. Cost: one pass over the leaves.
    void add(const FieldImage& field);
};

}  // namespace sculpt
