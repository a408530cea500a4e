#pragma once
/// @file tracked_mesh.h
/// @brief The triangle mesh a tracker moves with the surface: positions, triangles and a stable
///        id per vertex (what a point cache or a shape key is keyed by).
///
/// Vertex indices change when the mesh is compacted after a split or a collapse; ids never do:
/// a vertex keeps its id for as long as it exists, and a new vertex takes an id never used.

#include "core/mesh/surface_topology.h"
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

/// A change of a tracked mesh's connectivity, by vertex ids: what a sequence replays to keep
/// one set of vertices and triangles over the frames around it (tracked_sequence.h).
struct MeshEdit {
    enum class Kind : std::uint8_t { Split, Collapse };
    Kind kind = Kind::Split;
    /// Split: edge a -> b of one triangle (b -> a of the other) gained vertex `born` at its midpoint.
    /// Collapse: b was merged into a (a moved; b and the two triangles on the edge are gone).
    std::uint32_t a = 0, b = 0, born = 0;
};

/// Each vertex's triangles, as offsets into one list: vertex v's are list[start[v] .. start[v + 1]),
/// in triangle order.
struct VertexStars {
    std::vector<std::uint32_t> start, list;

    /// Over `triangles` of a mesh of `vertices` vertices, leaving out those `skip` marks (#F, when given).
    static VertexStars of(const std::vector<std::array<std::uint32_t, 3>>& triangles, std::size_t vertices,
                          const std::vector<std::uint8_t>* skip = nullptr);
};

/// An undirected edge between two vertex ids, as one key (smaller id in the high half).
inline std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b)
{
    return a < b ? (std::uint64_t(a) << 32) | b : (std::uint64_t(b) << 32) | a;
}

/// A directed edge between two vertex indices, as one key.
inline std::uint64_t halfEdgeKey(std::uint32_t from, std::uint32_t to) { return (std::uint64_t(from) << 32) | to; }

/// The topology of a closed mesh of `vertices` vertices (V - 3F/2 + F; shells by shared vertices).
SurfaceTopology surfaceTopology(const MeshArray<std::array<std::uint32_t, 3>>& triangles, std::size_t vertices);
SurfaceTopology surfaceTopology(const std::vector<std::array<std::uint32_t, 3>>& triangles, std::size_t vertices);

/// The smallest angle of a triangle, in degrees (0 for a degenerate one).
double smallestAngleDegrees(const openvdb::Vec3d& a, const openvdb::Vec3d& b, const openvdb::Vec3d& c);

/// How well shaped a tracked mesh is: what the tracker promises (edges within [e, 2e], few
/// triangles under 20 degrees) measured.
struct TrackedMeshQuality {
    std::size_t vertices = 0, triangles = 0;
    double smallestAngle = 180.0;                  ///< degrees, over all triangles
    double belowTwentyDegrees = 0.0;               ///< share of triangles
    double shortestEdge = 0.0, longestEdge = 0.0;  ///< world units
};
TrackedMeshQuality measureQuality(const TrackedMesh& mesh);

}  // namespace sculpt
