// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file dirty_region.h
/// @brief The set of leaf nodes an edit touched.
///
/// Every edit of a field image reports the leaves (8^3 voxel blocks, named by their origin in
/// index space) whose values or topology it changed. The incremental mesher re-meshes only the
/// blocks that read those voxels and the undo journal saves only those leaves, so the cost of an
/// edit follows the size of the edit, not of the model.

#include <openvdb/Types.h>

#include <set>
#include <vector>

namespace sculpt {

class DirtyRegion {
public:
    /// Marks the leaf containing voxel `ijk` (index space) as touched.
    void addVoxel(const openvdb::Coord& ijk);
    /// Marks every leaf of `other` as touched.
    void merge(const DirtyRegion& other);
    /// Forgets every touched leaf.
    void clear() { mLeafOrigins.clear(); }

    bool empty() const { return mLeafOrigins.empty(); }
    size_t leafCount() const { return mLeafOrigins.size(); }
    /// Origins of the touched leaves, sorted (deterministic for parallel consumers).
    std::vector<openvdb::Coord> leafOrigins() const;
    /// True if the leaf with this origin was touched.
    bool containsLeaf(const openvdb::Coord& leafOrigin) const;

    /// Origin of the leaf (8^3 voxels) that holds voxel `ijk`.
    static openvdb::Coord leafOriginOf(const openvdb::Coord& ijk);
    /// Origins of every leaf that overlaps the index box, x-major.
    static std::vector<openvdb::Coord> leafOriginsIn(const openvdb::CoordBBox& box);

private:
    std::set<openvdb::Coord> mLeafOrigins;
};

}  // namespace sculpt
