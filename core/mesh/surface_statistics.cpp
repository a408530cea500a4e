// SPDX-License-Identifier: Apache-2.0
#include "core/mesh/surface_statistics.h"

#include "core/base/union_find.h"

#include <algorithm>

namespace sculpt {

namespace {

/// Origin of the block that owns the vertex of `key`: the one its edge (or cell) starts in.
openvdb::Coord ownerOf(std::uint64_t key, int B)
{
    return {floorToMultiple(edgeKeyCoord(key, 0), B), floorToMultiple(edgeKeyCoord(key, 1), B),
            floorToMultiple(edgeKeyCoord(key, 2), B)};
}

}  // namespace

SurfaceStatistics::Tally SurfaceStatistics::tally(const BlockMesh& mesh)
{
    Tally t;
    UnionFind sets(mesh.positions.size());
    for (const auto& tri : mesh.triangles) {
        const openvdb::Vec3d a(mesh.positions[tri[0]].data()), b(mesh.positions[tri[1]].data()),
            c(mesh.positions[tri[2]].data());
        t.volume += a.dot(b.cross(c)) / 6.0;
        t.area += 0.5 * (b - a).cross(c - a).length();
        sets.join(tri[0], tri[1]);
        sets.join(tri[0], tri[2]);
    }
    t.triangles = mesh.triangles.size();
    t.component.resize(mesh.positions.size());
    std::vector<std::uint32_t> label(mesh.positions.size(), UINT32_MAX);
    for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) {
        std::uint32_t& l = label[sets.find(v)];
        if (l == UINT32_MAX) l = t.components++;
        t.component[v] = l;
    }
    return t;
}

void SurfaceStatistics::add(const Tally& t, double sign)
{
    mVolume += sign * t.volume;
    mArea += sign * t.area;
    mTriangles = sign > 0 ? mTriangles + t.triangles : mTriangles - t.triangles;
}

void SurfaceStatistics::update(const IncrementalMesher& mesher)
{
    if (mStarted && mesher.version() == mVersion) return;
    IncrementalMesher::Changes changes;
    if (mStarted) changes = mesher.changesSince(mVersion);
    else
        for (const auto& [origin, mesh] : mesher.blocks()) changes.updated.push_back(origin);
    for (const openvdb::Coord& origin : changes.removed) {
        if (auto it = mTallies.find(origin); it != mTallies.end()) {
            add(it->second, -1.0);
            mTallies.erase(it);
        }
    }
    for (const openvdb::Coord& origin : changes.updated) {
        if (auto it = mTallies.find(origin); it != mTallies.end()) add(it->second, -1.0);
        Tally& t = mTallies[origin] = tally(mesher.blocks().at(origin));
        add(t, 1.0);
    }
    mStarted = true;
    mVersion = mesher.version();
}

SurfaceTopology SurfaceStatistics::topology(const IncrementalMesher& mesher) const
{
    // One node per local component, numbered block after block.
    std::map<openvdb::Coord, std::uint32_t> firstNode;
    std::uint32_t nodes = 0;
    for (const auto& [origin, t] : mTallies) {
        firstNode[origin] = nodes;
        nodes += t.components;
    }
    UnionFind sets(nodes);
    SurfaceTopology topo;
    const int B = mesher.blockVoxels();
    for (const auto& [origin, t] : mTallies) {
        const BlockMesh& mesh = mesher.blocks().at(origin);
        topo.vertices += mesh.ownedCount;
        for (std::uint32_t v = mesh.ownedCount; v < mesh.positions.size(); ++v) {
            const openvdb::Coord owner = ownerOf(mesh.keys[v], B);
            const auto ownerMesh = mesher.blocks().find(owner);
            const auto ownerTally = mTallies.find(owner);
            bool found = false;
            if (ownerMesh != mesher.blocks().end() && ownerTally != mTallies.end()) {
                const auto first = ownerMesh->second.keys.begin();
                const auto last = first + ownerMesh->second.ownedCount;
                const auto at = std::lower_bound(first, last, mesh.keys[v]);
                if (at != last && *at == mesh.keys[v]) {
                    sets.join(firstNode[origin] + t.component[v],
                              firstNode[owner] + ownerTally->second.component[std::size_t(at - first)]);
                    found = true;
                }
            }
            if (!found) ++topo.vertices;  // owned by no block: counted here, once per use
        }
    }
    topo.shells = sets.count();
    topo.euler = static_cast<long long>(topo.vertices) - static_cast<long long>(mTriangles / 2);
    return topo;
}

}  // namespace sculpt
