// SPDX-License-Identifier: Apache-2.0
#include "core/mesh/polygon_soup.h"

#include <cstring>
#include <unordered_map>

namespace sculpt {

void fanPolygon(const std::vector<std::uint32_t>& ids, MeshArray<std::array<std::uint32_t, 3>>& triangles)
{
    for (std::size_t k = 1; k + 1 < ids.size(); ++k) triangles.push_back({ids[0], ids[k], ids[k + 1]});
}

namespace {

/// A position's bits, with -0 read as 0 so that the two meet.
struct PositionKey {
    std::uint32_t bits[3];
    bool operator==(const PositionKey& o) const { return std::memcmp(bits, o.bits, sizeof bits) == 0; }
};

struct PositionHash {
    std::size_t operator()(const PositionKey& k) const
    {
        return std::size_t(k.bits[0]) * 73856093u ^ std::size_t(k.bits[1]) * 19349663u ^
               std::size_t(k.bits[2]) * 83492791u;
    }
};

PositionKey keyOf(const std::array<float, 3>& p)
{
    PositionKey key;
    for (int a = 0; a < 3; ++a) {
        const float v = p[std::size_t(a)] == 0.0f ? 0.0f : p[std::size_t(a)];
        std::memcpy(&key.bits[a], &v, sizeof v);
    }
    return key;
}

}  // namespace

void joinCoincidentVertices(TriangleMesh& mesh)
{
    std::unordered_map<PositionKey, std::uint32_t, PositionHash> first;
    first.reserve(mesh.positions.size());
    std::vector<std::uint32_t> joined(mesh.positions.size());
    MeshArray<std::array<float, 3>> kept;
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const auto [at, added] = first.emplace(keyOf(mesh.positions[i]), std::uint32_t(kept.size()));
        if (added) kept.push_back(mesh.positions[i]);
        joined[i] = at->second;
    }
    std::size_t t = 0;
    for (const auto& tri : mesh.triangles) {
        const std::array<std::uint32_t, 3> j{joined[tri[0]], joined[tri[1]], joined[tri[2]]};
        if (j[0] != j[1] && j[1] != j[2] && j[0] != j[2]) mesh.triangles[t++] = j;
    }
    mesh.triangles.resize(t);
    mesh.positions = std::move(kept);
    mesh.normals.clear();
}

}  // namespace sculpt
