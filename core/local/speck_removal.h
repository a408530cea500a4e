// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file speck_removal.h
/// @brief Removes the specks an edit can leave: tiny closed shells of one sign (a few voxels of
///        inside in the outside, or a bubble of outside in the inside) where two surfaces meet
///        at a grazing angle, e.g. where a carving ball's boundary grazes the sculpt. A printer's
///        slicer, a component count and the Euler characteristic all see them; a sculptor cannot.

#include "core/field/field_image.h"
#include "core/local/capsule.h"

#include <openvdb/openvdb.h>

#include <vector>

namespace sculpt {

/// Voxels a speck may hold at most: a shell enclosing more is a feature and stays.
constexpr int kMaxSpeckVoxels = 8;

/// Flips the sign of every group of active voxels of one sign (6-connected, as marching cubes
/// joins them) that lies wholly inside `indexRegion` (a capsule in index space) and within a
/// voxel of the surface, holds at most `maxVoxels` voxels and touches no inactive voxel of its
/// sign: an island of inside or a bubble of outside. Voxels of the given leaves within a voxel of
/// the surface seed the search, so the cost follows the region's surface.
/// @return the voxels flipped.
std::size_t removeSpecks(openvdb::FloatGrid& grid, const Capsule& indexRegion,
                         const std::vector<openvdb::Coord>& leafOrigins, int maxVoxels = kMaxSpeckVoxels);

/// The same over the whole field, after an operation that changes all of it (smoothing,
/// offsetting, an import, a bake, a morph frame). Cost: linear in the band's surface voxels.
std::size_t removeSpecks(FieldImage& field, int maxVoxels = kMaxSpeckVoxels);

}  // namespace sculpt
