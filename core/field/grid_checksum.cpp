// SPDX-License-Identifier: Apache-2.0
#include "core/field/grid_checksum.h"

#include <openvdb/tree/LeafManager.h>
#include <tbb/parallel_for.h>

#include <cstring>
#include <sstream>
#include <vector>

namespace sculpt {

namespace {

/// FNV-1a over raw bytes: simple, stable across platforms and versions.
struct Fnv1a {
    std::uint64_t state = 1469598103934665603ull;
    void add(const void* data, size_t bytes)
    {
        const auto* p = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < bytes; ++i) state = (state ^ p[i]) * 1099511628211ull;
    }
    template <typename T>
    void add(const T& value)
    {
        add(&value, sizeof value);
    }
};

std::uint64_t leafHash(const openvdb::FloatTree::LeafNodeType& leaf)
{
    Fnv1a h;
    h.add(leaf.origin());
    const auto& mask = leaf.getValueMask();
    for (auto word = 0; word < int(mask.WORD_COUNT); ++word) h.add(mask.template getWord<openvdb::Index64>(word));
    h.add(leaf.buffer().data(), leaf.SIZE * sizeof(float));
    return h.state;
}

}  // namespace

std::uint64_t gridChecksum(const openvdb::FloatGrid& grid)
{
    const auto& tree = grid.tree();
    Fnv1a h;
    h.add(tree.background());
    for (auto it = tree.cbeginValueAll(); it; ++it) {
        if (it.isVoxelValue()) continue;
        h.add(it.getLevel());
        h.add(it.getCoord());
        h.add(*it);
        h.add(it.isValueOn());
    }
    openvdb::tree::LeafManager<const openvdb::FloatTree> leaves(tree);
    std::vector<std::uint64_t> leafHashes(leaves.leafCount());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, leaves.leafCount()), [&](const auto& r) {
        for (size_t i = r.begin(); i < r.end(); ++i) leafHashes[i] = leafHash(leaves.leaf(i));
    });
    h.add(leafHashes.data(), leafHashes.size() * sizeof(std::uint64_t));
    return h.state;
}

std::string formatChecksum(std::uint64_t checksum)
{
    std::ostringstream out;
    out << std::hex << checksum;
    return out.str();
}

}  // namespace sculpt
