// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file leaf_journal.h
/// @brief Copy-on-write record of the leaves an edit changed, for bit-exact undo and redo.
///
/// Before an edit first writes a leaf position, save() keeps what the tree held there: a copy of
/// the leaf, or the tile that covered it (its level, value and state), or nothing (a background
/// region outside the root's table). swap() puts every saved state back and keeps the states it
/// replaced, so a second swap() re-applies the edit: both restore the tree bit for bit, down to
/// the tiles a split produced. Memory follows the number of leaves edited, not the model.
///
/// A whole-model edit (a filter over the model) journals the whole grid instead: wholeGrid().
///
/// The tree must be a pruned level set (pruneLevelSet erases +background root tiles), which is
/// what every edit here leaves behind.

#include "core/field/dirty_region.h"
#include "core/field/field_image.h"

#include <map>
#include <memory>
#include <optional>

namespace sculpt {

class LeafJournal {
public:
    LeafJournal();
    ~LeafJournal();
    LeafJournal(LeafJournal&&) noexcept;
    LeafJournal& operator=(LeafJournal&&) noexcept;

    /// A journal holding a whole grid: swap() exchanges it with the field's (same transform).
    static LeafJournal wholeGrid(openvdb::FloatGrid::Ptr grid);

    /// Keeps the tree's state at this leaf position, unless this journal already holds it.
    void save(const openvdb::FloatTree& tree, const openvdb::Coord& leafOrigin);
    bool contains(const openvdb::Coord& leafOrigin) const;
    /// The same for a leaf position of the field's mask (FieldImage::mask): an edit of the mask is
    /// journalled with the surface's, and swap() restores both.
    void saveMask(const openvdb::FloatTree& maskTree, const openvdb::Coord& leafOrigin);
    /// Keeps the field's whole mask (null: none) before an edit that replaces it whole (clearing
    /// it): swap() exchanges it with the field's mask.
    void saveWholeMask(openvdb::FloatGrid::Ptr mask);

    /// What the tree held at a saved leaf position: that leaf (its values), or, where there was
    /// none, the value of the tile or background that covered it.
    struct SavedState {
        const openvdb::FloatTree::LeafNodeType* leaf = nullptr;
        float value = 0.0f;
    };
    /// The state saved at `leafOrigin`, if any (a whole-grid journal answers none).
    std::optional<SavedState> saved(const openvdb::Coord& leafOrigin) const;

    /// Restores every saved position and keeps what it replaced; marks them dirty in `field`.
    void swap(FieldImage& field);

    bool empty() const { return mEntries.empty() && mMaskEntries.empty() && !mWholeGrid && !mHasWholeMask; }
    std::size_t leafCount() const { return mEntries.size() + mMaskEntries.size(); }
    /// Heap bytes held (leaf copies and bookkeeping).
    std::size_t memoryBytes() const { return mBytes; }

private:
    struct Saved;
    static Saved capture(const openvdb::FloatTree& tree, const openvdb::Coord& leafOrigin);
    static void restore(openvdb::FloatTree& tree, const openvdb::Coord& leafOrigin, const Saved& saved);
    using Entries = std::map<openvdb::Coord, Saved>;
    /// Restores `entries` into `tree`, keeping what they replaced in their place; adds the leaf
    /// positions to `touched` and returns the bytes now held.
    static std::size_t swapEntries(openvdb::FloatTree& tree, Entries& entries, DirtyRegion& touched);

    Entries mEntries;
    Entries mMaskEntries;
    bool mHasWholeMask = false;
    openvdb::FloatGrid::Ptr mWholeMask;
    openvdb::FloatGrid::Ptr mWholeGrid;
    std::size_t mBytes = 0;
};

}  // namespace sculpt
