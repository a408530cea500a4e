// SPDX-License-Identifier: Apache-2.0
#include "core/tracking/tracked_mesh.h"

#include "core/base/union_find.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sculpt {

TrackedMesh TrackedMesh::of(const TriangleMesh& mesh, std::uint32_t firstId)
{
    TrackedMesh tracked;
    tracked.positions.reserve(mesh.positions.size());
    for (const auto& p : mesh.positions) tracked.positions.emplace_back(p[0], p[1], p[2]);
    tracked.triangles.assign(mesh.triangles.begin(), mesh.triangles.end());
    tracked.ids.resize(mesh.positions.size());
    for (std::uint32_t i = 0; i < tracked.ids.size(); ++i) tracked.ids[i] = firstId + i;
    tracked.nextId = firstId + std::uint32_t(tracked.ids.size());
    return tracked;
}

TriangleMesh TrackedMesh::triangleMesh() const
{
    TriangleMesh mesh;
    mesh.positions.reserve(positions.size());
    for (const auto& p : positions) mesh.positions.push_back({float(p.x()), float(p.y()), float(p.z())});
    mesh.triangles.assign(triangles.begin(), triangles.end());
    return mesh;
}

void TrackedMesh::dropUnusedVertices()
{
    std::vector<std::uint8_t> used(positions.size(), 0);
    for (const auto& t : triangles)
        for (const std::uint32_t v : t) used[v] = 1;
    std::vector<std::uint32_t> index(positions.size(), 0);
    std::uint32_t next = 0;
    for (std::size_t v = 0; v < used.size(); ++v) {
        index[v] = next;
        if (!used[v]) continue;
        positions[next] = positions[v];
        ids[next] = ids[v];
        ++next;
    }
    positions.resize(next);
    ids.resize(next);
    for (auto& t : triangles)
        for (std::uint32_t& v : t) v = index[v];
}

std::size_t TrackedMesh::dropShellsUnder(double extent)
{
    UnionFind shells(positions.size());
    for (const auto& t : triangles) {
        shells.join(t[0], t[1]);
        shells.join(t[1], t[2]);
    }
    std::vector<openvdb::BBoxd> box(positions.size());  // per shell, at its root
    for (const auto& t : triangles)
        for (const std::uint32_t v : t) box[shells.find(v)].expand(positions[v]);
    std::vector<std::uint8_t> under(positions.size(), 0);  // per shell, at its root
    std::size_t dropped = 0;
    for (std::uint32_t v = 0; v < positions.size(); ++v) {
        if (shells.find(v) != v || box[v].empty()) continue;
        const openvdb::Vec3d sides = box[v].extents();
        under[v] = std::max({sides.x(), sides.y(), sides.z()}) < extent;
        dropped += under[v];
    }
    if (dropped == 0) return 0;
    triangles.erase(std::remove_if(triangles.begin(), triangles.end(),
                                   [&](const std::array<std::uint32_t, 3>& t) { return under[shells.find(t[0])]; }),
                    triangles.end());
    dropUnusedVertices();
    return dropped;
}

}  // namespace sculpt
