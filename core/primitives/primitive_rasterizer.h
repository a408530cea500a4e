// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file primitive_rasterizer.h
/// @brief Bakes a primitive set into a narrow-band level set.
///
/// Only the leaves that meet some primitive's influence box are visited (never the whole
/// scene), and of those only the ones an interval bound of the field cannot prove wholly inside or
/// outside the band are sampled; at each voxel the set's field f is evaluated from the primitives whose influence
/// reaches it. g = iso - f is negative inside; g / |grad g| (central differences) is its distance
/// to the surface to first order (exact for a linear field), and one first-order redistancing
/// sweep of openvdb::tools::LevelSetTracker evens out what the kernels' curvature leaves.

#include "core/base/progress.h"
#include "core/field/field_image.h"
#include "core/primitives/primitive_set.h"

namespace sculpt {

/// Rasterizes `set` on the voxels of `xform` (linear, uniform) with the given band.
/// Cost: one field evaluation (over nearby primitives) per voxel of the touched leaves.
/// @throws InputError if the scene would not fit in memory.
FieldImage rasterizePrimitives(const PrimitiveSet& set, const openvdb::math::Transform& xform,
                               double halfWidthVoxels = FieldImage::kDefaultHalfWidthVoxels,
                               const Progress& progress = {});

}  // namespace sculpt
