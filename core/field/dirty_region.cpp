// SPDX-License-Identifier: Apache-2.0
#include "core/field/dirty_region.h"

namespace sculpt {

namespace {
constexpr openvdb::Int32 kLeafMask = ~openvdb::Int32(7);  // leaves are 8^3 voxels
}

openvdb::Coord DirtyRegion::leafOriginOf(const openvdb::Coord& ijk)
{
    return openvdb::Coord(ijk.x() & kLeafMask, ijk.y() & kLeafMask, ijk.z() & kLeafMask);
}

std::vector<openvdb::Coord> DirtyRegion::leafOriginsIn(const openvdb::CoordBBox& box)
{
    std::vector<openvdb::Coord> origins;
    if (box.empty()) return origins;
    const openvdb::Coord lo = leafOriginOf(box.min()), hi = box.max();
    for (int x = lo.x(); x <= hi.x(); x += 8)
        for (int y = lo.y(); y <= hi.y(); y += 8)
            for (int z = lo.z(); z <= hi.z(); z += 8) origins.emplace_back(x, y, z);
    return origins;
}

void DirtyRegion::addVoxel(const openvdb::Coord& ijk) { mLeafOrigins.insert(leafOriginOf(ijk)); }

void DirtyRegion::merge(const DirtyRegion& other)
{
    mLeafOrigins.insert(other.mLeafOrigins.begin(), other.mLeafOrigins.end());
}

std::vector<openvdb::Coord> DirtyRegion::leafOrigins() const { return {mLeafOrigins.begin(), mLeafOrigins.end()}; }

bool DirtyRegion::containsLeaf(const openvdb::Coord& leafOrigin) const { return mLeafOrigins.count(leafOrigin) != 0; }

}  // namespace sculpt
