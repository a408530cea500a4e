// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file tracked_mesh.h
/// @brief The triangle mesh a tracker moves with the surface: positions, triangles and a stable
///        id per vertex (what a point cache or a shape key is keyed by).
///
/// Vertex indices change when the mesh is compacted after a split or a collapse; ids never do:
/// a vertex keeps its id for as long as it exists, and a new vertex takes an id never used.

#include "core/mesh/triangle_mesh.h"

#include <openvdb/Types.h>

#include <array>
#include <cstdint>
#include <vector>

namespace sculpt {

struct TrackedMesh {
    std::vector<openvdb::Vec3d> positions;                ///< #V world points
    std::vector<std::array<std::uint32_t, 3>> triangles;  ///< #F, counter-clockwise from outside
    std::vector<std::uint32_t> ids;                       ///< #V stable vertex ids
    std::uint32_t nextId = 0;                             ///< the id the next new vertex takes

    /// A mesh of `mesh`'s vertices and triangles, ids firstId .. firstId + #V - 1.
    static TrackedMesh of(const TriangleMesh& mesh, std::uint32_t firstId = 0);
    /// Single precision, for the writers and the display (normals left empty).
    TriangleMesh triangleMesh() const;
    /// Drops the vertices no triangle uses, renumbering the rest in order (ids stay with them).
    void dropUnusedVertices();
    /// Drops the shells (triangles joined by shared vertices) whose bounding box is under
    /// `extent` on every side, and their vertices; returns how many shells it dropped.
    std::size_t dropShellsUnder(double extent);
};

}  // namespace sculpt
