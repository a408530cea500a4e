#pragma once
/// @file triangle_mesh.h
/// @brief An indexed triangle mesh in world coordinates: what meshers produce and writers save.

#include <array>
#include <cstdint>
#include <vector>

namespace sculpt {

struct TriangleMesh {
    /// #V world-space positions.
    std::vector<std::array<float, 3>> positions;
    /// #V unit normals pointing outwards (towards positive distance), or empty.
    std::vector<std::array<float, 3>> normals;
    /// #F triangles as indices into positions, counter-clockwise seen from outside.
    std::vector<std::array<std::uint32_t, 3>> triangles;
};

} // namespace sculpt
