// SPDX-License-Identifier: Apache-2.0
#include "ui/view/block_cluster.h"

#include <cmath>
#include <unordered_map>

namespace sculpt::ui {

BlockMesh clusterBlockMesh(const BlockMesh& mesh, double cellWorld)
{
    BlockMesh out;
    std::unordered_map<std::uint64_t, std::uint32_t> clusterOf;
    std::vector<std::uint32_t> counts;
    std::vector<std::uint32_t> remap(mesh.positions.size());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const auto& p = mesh.positions[v];
        std::uint64_t key = 0;
        for (int a = 0; a < 3; ++a)
            key = key << 21 | (std::uint64_t(std::int64_t(std::floor(p[a] / cellWorld)) + (1 << 20)) & 0x1FFFFF);
        auto [it, fresh] = clusterOf.try_emplace(key, std::uint32_t(out.positions.size()));
        if (fresh) {
            out.positions.push_back({0.f, 0.f, 0.f});
            out.normals.push_back({0.f, 0.f, 0.f});
            counts.push_back(0);
        }
        const std::uint32_t c = it->second;
        for (int a = 0; a < 3; ++a) {
            out.positions[c][a] += p[a];
            out.normals[c][a] += mesh.normals[v][a];
        }
        ++counts[c];
        remap[v] = c;
    }
    for (std::size_t c = 0; c < out.positions.size(); ++c) {
        float length = 0.f;
        for (int a = 0; a < 3; ++a) {
            out.positions[c][a] /= float(counts[c]);
            length += out.normals[c][a] * out.normals[c][a];
        }
        length = std::sqrt(length) > 0.f ? std::sqrt(length) : 1.f;
        for (int a = 0; a < 3; ++a) out.normals[c][a] /= length;
    }
    for (const auto& t : mesh.triangles) {
        const std::array<std::uint32_t, 3> r{remap[t[0]], remap[t[1]], remap[t[2]]};
        if (r[0] != r[1] && r[1] != r[2] && r[0] != r[2]) out.triangles.push_back(r);
    }
    return out;
}

}  // namespace sculpt::ui
