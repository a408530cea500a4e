// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file mesh_welder.h
/// @brief Joins block meshes into one shared-vertex mesh by their global edge keys.

#include "core/mesh/block_mesh.h"
#include "core/mesh/triangle_mesh.h"

#include <openvdb/Types.h>

#include <map>

namespace sculpt {

/// Welds blocks of B^3 voxels. Each block contributes its owned vertices (in block order, then
/// key order) and its triangles; a reference to a neighbour's vertex is found by binary search
/// in the owner's sorted keys. A vertex whose owner block is missing (possible only in a grid
/// whose signs change outside its leaves) is appended once. Parallel, deterministic.
TriangleMesh weldBlocks(const std::map<openvdb::Coord, BlockMesh>& blocks, int blockVoxels);

}  // namespace sculpt
