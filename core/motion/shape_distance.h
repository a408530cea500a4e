// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file shape_distance.h
/// @brief How far apart two surfaces are, read at the points where each crosses the grid's
///        edges: from one side (every point of one surface to the other) or from both (the
///        Hausdorff distance), with the mean beside the maximum, and the maximum again where the
///        reference shape is resolvable at its voxel size.
///
/// A grid of voxel h cannot hold a plate or a gap thinner than a few voxels, nor an edge
/// sharper than a voxel: level-set motion rounds them off and stalls a fraction of a voxel
/// away. A point of the reference surface is resolvable when its signed distance grows at
/// nearly unit rate for 1.5 voxels along its normal on both sides (phi(q -+ 1.5 h n) beyond
/// -+ 1.2 h): the shape is at least 2.4 voxels thick there, and as far from its next part.

#include "core/motion/wide_distance.h"

#include <openvdb/openvdb.h>

namespace sculpt {

/// Distances read at one or both surfaces' edge crossings, world units.
struct ShapeDistance {
    double maxWorld = 0.0;          ///< the farthest point
    double meanWorld = 0.0;         ///< the mean over every point: it keeps falling while any part travels
    double maxResolvedWorld = 0.0;  ///< the farthest point whose nearest reference point is resolvable
    double resolvedFraction = 1.0;  ///< points near a resolvable reference point (or far from it)
};

/// |phi_to| (trilinear) at the points where the zero set of `from` crosses grid edges; beyond its
/// band `to` reads its band's half width. `to` is the reference. All grids share their transform.
/// Cost: one pass over `from`'s active voxels, parallel.
ShapeDistance surfaceToField(const openvdb::FloatGrid& from, const openvdb::FloatGrid& to);
/// The same, read from `to`'s distance widened beyond its band.
ShapeDistance surfaceToField(const openvdb::FloatGrid& from, const WideDistance& to);

/// Both ways, b the reference: the surface of `a` to `bDistance` (b's distance, widened beyond
/// b's band) and the surface of `b` to `a`, whose band saturates that direction at its half
/// width: still the mean falls as a reaches more of b.
ShapeDistance twoSidedDistance(const openvdb::FloatGrid& a, const openvdb::FloatGrid& b, const WideDistance& bDistance);
/// Both ways with both distances widened: the true Hausdorff distance, b the reference.
ShapeDistance twoSidedDistance(const openvdb::FloatGrid& a, const WideDistance& aDistance, const openvdb::FloatGrid& b,
                               const WideDistance& bDistance);

}  // namespace sculpt
