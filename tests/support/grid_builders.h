// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file grid_builders.h
/// @brief Hand-made level sets for tests: a few explicit voxel values in an outside field, a
///        field moved, two pieces apart.

#include "core/field/field_image.h"
#include "core/field/piece.h"

#include <map>
#include <vector>

namespace sculpt::test {

/// A level set (voxel size 1, background 3) whose voxels in `values` hold the given values and
/// every other voxel in the box around them holds +1: explicit corners surrounded by outside, so
/// the surface closes in the neighbouring cells.
FieldImage fieldFromVoxels(const std::map<openvdb::Coord, float>& values);

/// `field` moved by `by` (world units): the same voxels on a translated lattice.
FieldImage translated(const FieldImage& field, const openvdb::Vec3d& by);

/// A document's two pieces 14 apart: "body" (radius 10 at the origin, voxel 0.5, to x = 10) and
/// "ball" (radius 6, placed at x = 30: from x = 24).
std::vector<Piece> bodyAndBallApart();

}  // namespace sculpt::test
