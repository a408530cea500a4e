// SPDX-License-Identifier: Apache-2.0
#include "core/mesh/mesh_welder.h"

#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <limits>
#include <unordered_map>

namespace sculpt {

namespace {

constexpr std::uint32_t kMissing = std::numeric_limits<std::uint32_t>::max();

struct Welder {
    std::vector<openvdb::Coord> origins;
    std::vector<const BlockMesh*> meshes;
    std::vector<std::uint32_t> vertexOffset, triangleOffset;
    int B;

    Welder(const std::map<openvdb::Coord, BlockMesh>& blocks, int blockVoxels) : B(blockVoxels)
    {
        std::uint32_t vertices = 0, triangles = 0;
        for (const auto& [origin, mesh] : blocks) {
            origins.push_back(origin);
            meshes.push_back(&mesh);
            vertexOffset.push_back(vertices);
            triangleOffset.push_back(triangles);
            vertices += mesh.ownedCount;
            triangles += std::uint32_t(mesh.triangles.size());
        }
        vertexOffset.push_back(vertices);
        triangleOffset.push_back(triangles);
    }

    /// Global index of a vertex owned by another block, or kMissing.
    std::uint32_t lookup(std::uint64_t key) const
    {
        const openvdb::Coord owner(edgeKeyCoord(key, 0) & ~(B - 1), edgeKeyCoord(key, 1) & ~(B - 1),
                                   edgeKeyCoord(key, 2) & ~(B - 1));
        const auto block = std::lower_bound(origins.begin(), origins.end(), owner);
        if (block == origins.end() || *block != owner) return kMissing;
        const size_t b = size_t(block - origins.begin());
        const auto& keys = meshes[b]->keys;
        const auto end = keys.begin() + meshes[b]->ownedCount;
        const auto found = std::lower_bound(keys.begin(), end, key);
        if (found == end || *found != key) return kMissing;
        return vertexOffset[b] + std::uint32_t(found - keys.begin());
    }

    /// Copies block b's owned vertices and its triangles; false if a vertex had no owner.
    bool copyBlock(size_t b, TriangleMesh& out, std::vector<std::uint32_t>& global) const
    {
        const BlockMesh& mesh = *meshes[b];
        std::copy_n(mesh.positions.begin(), mesh.ownedCount, out.positions.begin() + vertexOffset[b]);
        std::copy_n(mesh.normals.begin(), mesh.ownedCount, out.normals.begin() + vertexOffset[b]);
        global.resize(mesh.keys.size());
        bool complete = true;
        for (std::uint32_t j = 0; j < global.size(); ++j) {
            global[j] = j < mesh.ownedCount ? vertexOffset[b] + j : lookup(mesh.keys[j]);
            complete = complete && global[j] != kMissing;
        }
        auto dst = out.triangles.begin() + triangleOffset[b];
        for (const auto& tri : mesh.triangles) *dst++ = {global[tri[0]], global[tri[1]], global[tri[2]]};
        return complete;
    }

    /// Serial pass: append vertices whose owner block did not produce them.
    void addOrphans(TriangleMesh& out) const
    {
        std::unordered_map<std::uint64_t, std::uint32_t> orphans;
        for (size_t b = 0; b < meshes.size(); ++b) {
            const BlockMesh& mesh = *meshes[b];
            for (size_t t = 0; t < mesh.triangles.size(); ++t) {
                auto& tri = out.triangles[triangleOffset[b] + t];
                for (int k = 0; k < 3; ++k) {
                    if (tri[k] != kMissing) continue;
                    const std::uint32_t local = mesh.triangles[t][k];
                    auto [it, added] = orphans.emplace(mesh.keys[local], std::uint32_t(out.positions.size()));
                    if (added) {
                        out.positions.push_back(mesh.positions[local]);
                        out.normals.push_back(mesh.normals[local]);
                    }
                    tri[k] = it->second;
                }
            }
        }
    }
};

}  // namespace

TriangleMesh weldBlocks(const std::map<openvdb::Coord, BlockMesh>& blocks, int blockVoxels)
{
    const Welder welder(blocks, blockVoxels);
    TriangleMesh out;
    out.positions.resize(welder.vertexOffset.back());
    out.normals.resize(welder.vertexOffset.back());
    out.triangles.resize(welder.triangleOffset.back());
    const bool complete = tbb::parallel_reduce(
        tbb::blocked_range<size_t>(0, welder.meshes.size()), true,
        [&](const auto& r, bool ok) {
            std::vector<std::uint32_t> global;
            for (size_t b = r.begin(); b < r.end(); ++b) ok = welder.copyBlock(b, out, global) && ok;
            return ok;
        },
        [](bool a, bool b) { return a && b; });
    if (!complete) welder.addOrphans(out);
    return out;
}

}  // namespace sculpt
