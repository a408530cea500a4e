// SPDX-License-Identifier: Apache-2.0
#include "core/field/leaf_journal.h"

#include <algorithm>
#include <vector>

namespace sculpt {

namespace {

using LeafT = openvdb::FloatTree::LeafNodeType;
constexpr int kLeafDepth = int(openvdb::FloatTree::DEPTH) - 1;
/// Per-entry bookkeeping of a std::map node, roughly.
constexpr std::size_t kEntryOverhead = 64;

}  // namespace

/// What the tree held at a leaf position: a leaf, a tile at some level, or nothing.
struct LeafJournal::Saved {
    std::unique_ptr<LeafT> leaf;
    int level = -1;  ///< tile level (1 = leaf-sized ... root), -1 for background outside the root
    float value = 0.0f;
    bool active = false;

    std::size_t memoryBytes() const { return kEntryOverhead + (leaf ? leaf->memUsage() : 0); }
};

LeafJournal::LeafJournal() = default;
LeafJournal::~LeafJournal() = default;
LeafJournal::LeafJournal(LeafJournal&&) noexcept = default;
LeafJournal& LeafJournal::operator=(LeafJournal&&) noexcept = default;

LeafJournal::Saved LeafJournal::capture(const openvdb::FloatTree& tree, const openvdb::Coord& leafOrigin)
{
    Saved saved;
    if (const LeafT* leaf = tree.probeConstLeaf(leafOrigin)) {
        saved.leaf = std::make_unique<LeafT>(*leaf);
        return saved;
    }
    const int depth = tree.getValueDepth(leafOrigin);
    saved.level = depth < 0 ? -1 : kLeafDepth - depth;
    saved.value = tree.getValue(leafOrigin);
    saved.active = tree.isValueOn(leafOrigin);
    return saved;
}

bool LeafJournal::contains(const openvdb::Coord& leafOrigin) const { return mEntries.count(leafOrigin) != 0; }

std::optional<LeafJournal::SavedState> LeafJournal::saved(const openvdb::Coord& leafOrigin) const
{
    const auto it = mEntries.find(leafOrigin);
    if (it == mEntries.end()) return std::nullopt;
    return SavedState{it->second.leaf.get(), it->second.value};
}

void LeafJournal::save(const openvdb::FloatTree& tree, const openvdb::Coord& leafOrigin)
{
    if (contains(leafOrigin)) return;
    Saved saved = capture(tree, leafOrigin);
    mBytes += saved.memoryBytes();
    mEntries.emplace(leafOrigin, std::move(saved));
}

void LeafJournal::saveWholeMask(openvdb::FloatGrid::Ptr mask)
{
    mHasWholeMask = true;
    mBytes += mask ? mask->memUsage() : 0;
    mWholeMask = std::move(mask);
}

void LeafJournal::saveMask(const openvdb::FloatTree& maskTree, const openvdb::Coord& leafOrigin)
{
    if (mMaskEntries.count(leafOrigin)) return;
    Saved saved = capture(maskTree, leafOrigin);
    mBytes += saved.memoryBytes();
    mMaskEntries.emplace(leafOrigin, std::move(saved));
}

void LeafJournal::restore(openvdb::FloatTree& tree, const openvdb::Coord& leafOrigin, const Saved& saved)
{
    if (saved.leaf) {
        tree.addLeaf(new LeafT(*saved.leaf));
    } else if (saved.level >= 0) {
        // A tile a split produced may already be back inside a coarser tile restored before it;
        // adding it again would split that tile anew (and leave a node of background tiles).
        // A background tile needs no restoring where the background is already (an edit that first
        // made this region, and whose first save restored it to nothing, saved the rest as tiles).
        const int depth = tree.getValueDepth(leafOrigin);
        const bool sameValue = !tree.probeConstLeaf(leafOrigin) && tree.getValue(leafOrigin) == saved.value &&
                               tree.isValueOn(leafOrigin) == saved.active;
        const bool background = saved.value == tree.background() && !saved.active;
        const bool covered = sameValue && (background || (depth >= 0 && kLeafDepth - depth >= saved.level));
        if (!covered) tree.addTile(openvdb::Index(saved.level), leafOrigin, saved.value, saved.active);
    } else {
        // Nothing was there: a background root tile, then erased like pruneLevelSet does.
        tree.addTile(openvdb::FloatTree::RootNodeType::LEVEL, leafOrigin, tree.background(), false);
        tree.root().eraseBackgroundTiles();
    }
}

LeafJournal LeafJournal::wholeGrid(openvdb::FloatGrid::Ptr grid)
{
    LeafJournal journal;
    journal.mBytes = grid->memUsage();
    journal.mWholeGrid = std::move(grid);
    return journal;
}

void LeafJournal::swap(FieldImage& field)
{
    if (mWholeGrid) {
        field.swapGrid(mWholeGrid);
        mBytes = mWholeGrid->memUsage();
        return;
    }
    DirtyRegion touched;
    mBytes = swapEntries(field.mutableGrid().tree(), mEntries, touched);
    if (!mMaskEntries.empty()) mBytes += swapEntries(field.mutableMask().tree(), mMaskEntries, touched);
    if (mHasWholeMask) {
        openvdb::FloatGrid::Ptr current = field.maskPtr();
        for (const openvdb::FloatGrid::Ptr& mask : {current, mWholeMask})
            if (mask)
                for (auto leaf = mask->tree().cbeginLeaf(); leaf; ++leaf) touched.addVoxel(leaf->origin());
        field.setMask(mWholeMask);
        mWholeMask = std::move(current);
        mBytes += mWholeMask ? mWholeMask->memUsage() : 0;
    }
    field.markDirty(touched);
}

std::size_t LeafJournal::swapEntries(openvdb::FloatTree& tree, Entries& entries, DirtyRegion& touched)
{
    // Capture everything first: restoring a coarse tile wipes the leaves below it.
    Entries current;
    std::size_t currentBytes = 0;
    for (const auto& [origin, saved] : entries) {
        Saved now = capture(tree, origin);
        currentBytes += now.memoryBytes();
        current.emplace(origin, std::move(now));
        touched.addVoxel(origin);
    }
    // Coarsest first, leaves last: a saved state never nests inside another's region, except
    // the tiles one split produced, which all agree.
    std::vector<std::pair<int, openvdb::Coord>> order;
    for (const auto& [origin, saved] : entries)
        order.emplace_back(saved.leaf ? 0 : saved.level < 0 ? 99 : saved.level, origin);
    std::sort(order.begin(), order.end(), [](const auto& a, const auto& b) {
        return a.first > b.first || (a.first == b.first && a.second < b.second);
    });
    for (const auto& [rank, origin] : order) restore(tree, origin, entries.at(origin));
    tree.clearAllAccessors();
    entries = std::move(current);
    return currentBytes;
}

}  // namespace sculpt
