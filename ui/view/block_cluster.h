// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file block_cluster.h
/// @brief A mesh's coarse twin by vertex clustering: what the display draws far away and what
///        the ghost of a target shows.

#include "core/mesh/block_mesh.h"

namespace sculpt::ui {

/// The mesh with its vertices merged into clusters of `cellWorld` (a cube grid fixed in world
/// space, so neighbouring blocks and chunks cluster alike): about (cell / voxel)^2 times fewer
/// triangles. Degenerate triangles are dropped.
BlockMesh clusterBlockMesh(const BlockMesh& mesh, double cellWorld);

}  // namespace sculpt::ui
