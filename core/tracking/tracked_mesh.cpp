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

double smallestAngleDegrees(const openvdb::Vec3d& a, const openvdb::Vec3d& b, const openvdb::Vec3d& c)
{
    const auto angle = [](const openvdb::Vec3d& at, const openvdb::Vec3d& p, const openvdb::Vec3d& q) {
        const openvdb::Vec3d u = p - at, v = q - at;
        const double lengths = u.length() * v.length();
        return lengths > 0.0 ? std::acos(std::clamp(u.dot(v) / lengths, -1.0, 1.0)) : 0.0;
    };
    const double smallest = std::min({angle(a, b, c), angle(b, c, a), angle(c, a, b)});
    return smallest * 180.0 / M_PI;
}

TrackedMeshQuality measureQuality(const TrackedMesh& mesh)
{
    TrackedMeshQuality q{mesh.positions.size(), mesh.triangles.size()};
    if (mesh.triangles.empty()) return q;
    std::size_t below = 0;
    q.shortestEdge = std::numeric_limits<double>::max();
    for (const auto& t : mesh.triangles) {
        const double angle = smallestAngleDegrees(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]);
        q.smallestAngle = std::min(q.smallestAngle, angle);
        below += angle < 20.0;
        for (int k = 0; k < 3; ++k) {
            const double length = (mesh.positions[t[k]] - mesh.positions[t[(k + 1) % 3]]).length();
            q.shortestEdge = std::min(q.shortestEdge, length);
            q.longestEdge = std::max(q.longestEdge, length);
        }
    }
    q.belowTwentyDegrees = double(below) / double(mesh.triangles.size());
    return q;
}

}  // namespace sculpt
