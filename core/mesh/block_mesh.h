// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file block_mesh.h
/// @brief The cached surface of one block of cells.

#include <array>
#include <cstdint>
#include <vector>

namespace sculpt {

/// Surface of the cells whose minimum corner lies in one block of B^3 voxels.
///
/// Every vertex lies on a grid edge and carries that edge's global key (edgeKey), so blocks
/// weld exactly. The first `ownedCount` vertices are *owned*: their edge starts inside this
/// block; they are sorted by key so neighbours can find them. The remaining vertices lie on the
/// block's far faces and are owned by a neighbour, which computes them bit for bit alike.
struct BlockMesh {
    std::vector<std::array<float, 3>> positions;          ///< world space
    std::vector<std::array<float, 3>> normals;            ///< unit, outwards (towards positive distance)
    std::vector<std::uint64_t> keys;                      ///< edgeKey of each vertex
    std::vector<std::array<std::uint32_t, 3>> triangles;  ///< local indices, CCW from outside
    std::uint32_t ownedCount = 0;
    std::uint64_t version = 0;  ///< mesher version at which this mesh was made

    bool empty() const { return triangles.empty(); }
    /// Heap bytes held by this mesh.
    std::size_t memoryBytes() const;
};

/// The multiple of `size` at or below `v` (floor division, for negative coordinates too): the
/// origin of the block or chunk holding coordinate v.
inline int floorToMultiple(int v, int size) { return v >= 0 ? v / size * size : -((-v + size - 1) / size) * size; }

/// Global key of the grid edge from voxel (x, y, z) along `axis`: 20 bits per coordinate
/// (|x|, |y|, |z| < 2^19) and 2 bits of axis. Axis 3 names the centre vertex of cell (x, y, z)
/// (see mc::kCentre).
inline std::uint64_t edgeKey(int x, int y, int z, int axis)
{
    constexpr std::int64_t bias = 1 << 19;
    return (std::uint64_t(x + bias) << 42) | (std::uint64_t(y + bias) << 22) | (std::uint64_t(z + bias) << 2) |
           std::uint64_t(axis);
}

/// Voxel coordinate `axis` (0..2) of the start of the edge named by `key`.
inline int edgeKeyCoord(std::uint64_t key, int axis)
{
    constexpr std::int64_t bias = 1 << 19;
    const int shift = axis == 0 ? 42 : axis == 1 ? 22 : 2;
    return int(std::int64_t(key >> shift & 0xFFFFF) - bias);
}

}  // namespace sculpt
