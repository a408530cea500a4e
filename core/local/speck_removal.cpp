// SPDX-License-Identifier: Apache-2.0
#include "core/local/speck_removal.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace sculpt {

namespace {

/// Marching cubes joins voxels of one sign across faces, not across edges or corners: a group
/// 6-connected is one shell of the mesh.
const openvdb::Coord kFaceNeighbours[] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

/// Whether the group of `seed`'s sign is a speck: walked through face neighbours, it ends within
/// `maxVoxels` voxels, all active, inside the region and within a voxel of the surface (a group
/// holding a voxel deeper than that is at least two voxels thick everywhere: not debris).
bool isSpeck(const openvdb::FloatGrid::Accessor& acc, const openvdb::Coord& seed, const Capsule& region,
             std::size_t maxVoxels, float deep, std::vector<openvdb::Coord>& group)
{
    const bool inside = acc.getValue(seed) < 0.0f;
    group.assign(1, seed);
    for (std::size_t next = 0; next < group.size(); ++next) {
        for (const openvdb::Coord& step : kFaceNeighbours) {
            const openvdb::Coord n = group[next] + step;
            const float phi = acc.getValue(n);
            if ((phi < 0.0f) != inside || std::find(group.begin(), group.end(), n) != group.end()) continue;
            if (std::abs(phi) > deep || group.size() == maxVoxels || !acc.isValueOn(n) ||
                !region.contains(n.asVec3d())) {
                return false;
            }
            group.push_back(n);
        }
    }
    return true;
}

/// Whether `c` could be the last voxel of its group in (x, y, z) order: then its +x, +y and +z
/// neighbours are all of the other sign. Every group has such a voxel, so seeding only these
/// finds every speck, and most of the surface is rejected by three lookups.
bool lastOfItsGroup(const openvdb::FloatGrid::Accessor& acc, const openvdb::Coord& c, bool inside)
{
    return (acc.getValue(c.offsetBy(1, 0, 0)) < 0.0f) != inside &&
           (acc.getValue(c.offsetBy(0, 1, 0)) < 0.0f) != inside && (acc.getValue(c.offsetBy(0, 0, 1)) < 0.0f) != inside;
}

}  // namespace

std::size_t removeSpecks(openvdb::FloatGrid& grid, const Capsule& indexRegion,
                         const std::vector<openvdb::Coord>& leafOrigins, int maxVoxels)
{
    using LeafT = openvdb::FloatTree::LeafNodeType;
    const float h = float(grid.voxelSize()[0]);
    auto acc = grid.getAccessor();
    std::vector<openvdb::Coord> group;
    std::size_t flipped = 0;
    for (const openvdb::Coord& origin : leafOrigins) {
        LeafT* leaf = acc.probeLeaf(origin);
        if (!leaf) continue;
        for (auto it = leaf->beginValueOn(); it; ++it) {
            if (!(std::abs(*it) < h) || !lastOfItsGroup(acc, it.getCoord(), *it < 0.0f) ||
                !indexRegion.contains(it.getCoord().asVec3d())) {
                continue;
            }
            if (!isSpeck(acc, it.getCoord(), indexRegion, std::size_t(maxVoxels), h, group)) continue;
            for (const openvdb::Coord& c : group) acc.setValueOn(c, -acc.getValue(c));
            flipped += group.size();
        }
    }
    return flipped;
}

std::size_t removeSpecks(FieldImage& field, int maxVoxels)
{
    const Capsule everywhere{openvdb::Vec3d(0.0), openvdb::Vec3d(0.0), 4.0 * double(kMaxIndexCoordinate)};
    return removeSpecks(field.mutableGrid(), everywhere, field.allLeaves().leafOrigins(), maxVoxels);
}

}  // namespace sculpt
