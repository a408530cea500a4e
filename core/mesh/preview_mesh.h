// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file preview_mesh.h
/// @brief A quick, coarse surface of a large field image: what the window shows while the full
///        mesh is still being made.
///
/// The field is point-sampled at every s-th voxel (s a power of two) into a level set of voxel
/// size s h, which is meshed as any field: about s^2 fewer triangles and s^3 less work. The
/// samples are the field's own distances, so the coarse surface lies within about a coarse
/// voxel of the true one. Every voxel of a coarse leaf is sampled, inactive ones too (the band,
/// 6 voxels thick, leaves most coarse voxels without an active sample; the fine value still has
/// the right sign); the tiles between leaves take theirs from OpenVDB's signed flood fill.

#include "core/field/field_image.h"
#include "core/mesh/triangle_mesh.h"

namespace sculpt {

/// The smallest power-of-two stride (1 to 8) whose preview is estimated to hold at most
/// `triangleBudget` triangles; 1 means the full mesh fits (no preview needed). The estimate is
/// the band's active voxels over its half width (marching cubes makes about two triangles per
/// surface voxel, and the band is two half widths thick): no meshing, linear in the leaves.
int previewStride(const FieldImage& field, std::size_t triangleBudget);

/// The welded zero iso-surface of `field` sampled at every `stride`-th voxel (1, 2, 4 or 8),
/// in world coordinates. Cost: linear in the leaves, then meshing about stride^3 fewer voxels.
TriangleMesh previewMesh(const FieldImage& field, int stride);

}  // namespace sculpt
