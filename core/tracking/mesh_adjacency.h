// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file mesh_adjacency.h
/// @brief How an indexed triangle mesh's pieces meet: each vertex's triangles, edges as keys,
///        and the topology (Euler characteristic, shells) of a closed one.

#include "core/mesh/surface_topology.h"
#include "core/mesh/triangle_mesh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace sculpt {

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

}  // namespace sculpt
