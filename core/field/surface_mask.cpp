// SPDX-License-Identifier: Apache-2.0
#include "core/field/surface_mask.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <mutex>
#include <vector>

namespace sculpt {

namespace {

using LeafT = openvdb::FloatTree::LeafNodeType;

/// Leaf origins of either tree, sorted, each once.
std::vector<openvdb::Coord> leafOriginsOfEither(const openvdb::FloatTree& a, const openvdb::FloatTree& b)
{
    std::vector<openvdb::Coord> origins;
    for (auto leaf = a.cbeginLeaf(); leaf; ++leaf) origins.push_back(leaf->origin());
    for (auto leaf = b.cbeginLeaf(); leaf; ++leaf) origins.push_back(leaf->origin());
    std::sort(origins.begin(), origins.end());
    origins.erase(std::unique(origins.begin(), origins.end()), origins.end());
    return origins;
}

}  // namespace

void keepMasked(FieldImage& field, const openvdb::FloatGrid& before)
{
    const openvdb::FloatGrid* mask = field.mask();
    if (!mask) return;
    openvdb::FloatGrid& grid = field.mutableGrid();
    const float background = grid.background();
    const std::vector<openvdb::Coord> origins = leafOriginsOfEither(grid.tree(), before.tree());
    // Leaves the edit has are held in place, in parallel; where it left a tile, the held values
    // are gathered and written afterwards (a new leaf changes the tree's structure).
    std::vector<std::pair<openvdb::Coord, std::vector<BandValue>>> newLeaves;
    std::mutex newLeavesLock;
    std::vector<char> changed(origins.size(), 0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, origins.size()), [&](const auto& range) {
        const MaskReader reader(*mask);
        const auto beforeAcc = before.getConstAccessor();
        const auto afterAcc = grid.getConstAccessor();
        for (std::size_t i = range.begin(); i < range.end(); ++i) {
            LeafT* leaf = grid.tree().probeLeaf(origins[i]);
            std::vector<BandValue> held(leaf ? 0 : LeafT::SIZE);
            for (auto ijk = openvdb::CoordBBox::createCube(origins[i], LeafT::DIM).begin(); ijk; ++ijk) {
                const openvdb::Index k = LeafT::coordToOffset(*ijk);
                const float was = beforeAcc.getValue(*ijk), now = leaf ? leaf->getValue(k) : afterAcc.getValue(*ijk);
                BandValue value = toBand(now, background);
                if (was != now) value = maskedValue(was, now, reader.at(*ijk), background);
                if (!leaf) {
                    held[k] = value;
                    changed[i] |= value.value != now;
                } else if (value.value != now || value.active != leaf->isValueOn(k)) {
                    setBandValue(*leaf, k, value);
                    changed[i] = 1;
                }
            }
            if (!leaf && changed[i]) {
                const std::lock_guard<std::mutex> hold(newLeavesLock);
                newLeaves.emplace_back(origins[i], std::move(held));
            }
        }
    });
    auto acc = grid.getAccessor();
    for (const auto& [origin, values] : newLeaves) {
        LeafT* leaf = acc.touchLeaf(origin);
        for (openvdb::Index k = 0; k < LeafT::SIZE; ++k) setBandValue(*leaf, k, values[k]);
    }
    DirtyRegion touched;
    for (std::size_t i = 0; i < origins.size(); ++i)
        if (changed[i]) touched.addVoxel(origins[i]);
    field.markDirty(touched);
}

}  // namespace sculpt
