// SPDX-License-Identifier: Apache-2.0
#include "core/tracking/mesh_adjacency.h"

#include "core/base/union_find.h"

#include <algorithm>

namespace sculpt {

VertexStars VertexStars::of(const std::vector<std::array<std::uint32_t, 3>>& triangles, std::size_t vertices,
                            const std::vector<std::uint8_t>* skip)
{
    const auto kept = [&](std::size_t t) { return !skip || !(*skip)[t]; };
    VertexStars stars;
    stars.start.assign(vertices + 1, 0);
    for (std::size_t t = 0; t < triangles.size(); ++t)
        if (kept(t))
            for (const std::uint32_t v : triangles[t]) ++stars.start[v + 1];
    for (std::size_t v = 0; v < vertices; ++v) stars.start[v + 1] += stars.start[v];
    stars.list.assign(stars.start.back(), 0);
    std::vector<std::uint32_t> fill(stars.start.begin(), stars.start.end() - 1);
    for (std::uint32_t t = 0; t < triangles.size(); ++t)
        if (kept(t))
            for (const std::uint32_t v : triangles[t]) stars.list[fill[v]++] = t;
    return stars;
}

namespace {

template <typename Triangles>
SurfaceTopology topologyOf(const Triangles& triangles, std::size_t vertices)
{
    UnionFind shells(vertices);
    std::vector<std::uint8_t> used(vertices, 0);
    for (const auto& t : triangles) {
        shells.join(t[0], t[1]);
        shells.join(t[1], t[2]);
        for (const std::uint32_t v : t) used[v] = 1;
    }
    std::size_t count = 0, usedCount = 0;
    for (std::uint32_t v = 0; v < vertices; ++v) {
        usedCount += used[v];
        count += used[v] && shells.find(v) == v;
    }
    const auto f = (long long)triangles.size();
    return {usedCount, (long long)usedCount - 3 * f / 2 + f, count};
}

}  // namespace

SurfaceTopology surfaceTopology(const MeshArray<std::array<std::uint32_t, 3>>& triangles, std::size_t vertices)
{
    return topologyOf(triangles, vertices);
}

SurfaceTopology surfaceTopology(const std::vector<std::array<std::uint32_t, 3>>& triangles, std::size_t vertices)
{
    return topologyOf(triangles, vertices);
}

}  // namespace sculpt
