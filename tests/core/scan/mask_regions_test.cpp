// SPDX-License-Identifier: Apache-2.0
// Face-connected regions of bit masks (core/mask_regions.h): the same regions as OpenVDB's
// extractActiveVoxelSegmentMasks on random masks, through leaf faces and active tiles.

#include "core/scan/mask_regions.h"

#include <gtest/gtest.h>
#include <openvdb/tools/LevelSetUtil.h>

#include <algorithm>
#include <random>
#include <vector>

// Clang and GCC mangle this signature differently (the dependent Ptr inside the allocator), so
// the sanitizer tree (clang) cannot link against the instantiation in Debian's GCC-built
// libopenvdb: clang instantiates it here (GCC links Debian's; instantiating it costs a minute).
#ifdef __clang__
template void openvdb::tools::extractActiveVoxelSegmentMasks<openvdb::BoolTree>(const openvdb::BoolTree&,
                                                                                std::vector<openvdb::BoolTree::Ptr>&);
#endif

namespace sculpt {
namespace {

/// Voxel counts of the regions, largest first.
std::vector<openvdb::Index64> regionSizes(const openvdb::BoolTree& mask)
{
    std::vector<openvdb::Index64> sizes;
    forEachConnectedRegion(mask, [&](const MaskRegion& region) { sizes.push_back(region.voxelCount()); });
    std::sort(sizes.rbegin(), sizes.rend());
    return sizes;
}

std::vector<openvdb::Index64> openVdbRegionSizes(const openvdb::BoolTree& mask)
{
    std::vector<openvdb::BoolTree::Ptr> segments;
    openvdb::tools::extractActiveVoxelSegmentMasks(mask, segments);
    std::vector<openvdb::Index64> sizes;
    for (const auto& segment : segments) sizes.push_back(segment->activeVoxelCount());
    std::sort(sizes.rbegin(), sizes.rend());
    return sizes;
}

TEST(MaskRegions, AgreeWithOpenVdbOnRandomMasks)
{
    std::mt19937 random(7);
    for (const double density : {0.3, 0.45}) {  // below and above the percolation threshold (0.31)
        openvdb::BoolTree mask(false);
        std::bernoulli_distribution on(density);
        for (int z = -13; z < 27; ++z) {
            for (int y = -5; y < 30; ++y) {
                for (int x = -20; x < 17; ++x) {
                    if (on(random)) mask.setValueOn(openvdb::Coord(x, y, z));
                }
            }
        }
        const auto ours = regionSizes(mask);
        EXPECT_GT(ours.size(), 10u) << density;
        EXPECT_EQ(ours, openVdbRegionSizes(mask)) << density;
    }
}

TEST(MaskRegions, ActiveTilesAndLeafFacesConnect)
{
    openvdb::BoolTree mask(false);
    mask.fill(openvdb::CoordBBox(openvdb::Coord(0), openvdb::Coord(127)), true, true);  // one tile of 128^3
    mask.setValueOn(openvdb::Coord(128, 5, 5));                                         // touches the tile's face
    mask.setValueOn(openvdb::Coord(129, 6, 5));  // touches that voxel along an edge only: apart
    const MaskRegion region = connectedRegion(mask, openvdb::Coord(128, 5, 5));
    EXPECT_EQ(region.voxelCount(), openvdb::Index64(128) * 128 * 128 + 1);
    const openvdb::BoolTree::Ptr tree = region.tree();
    EXPECT_EQ(tree->activeVoxelCount(), region.voxelCount());
    EXPECT_TRUE(tree->isValueOn(openvdb::Coord(127, 127, 127)));
    EXPECT_FALSE(tree->isValueOn(openvdb::Coord(129, 6, 5)));
    EXPECT_EQ(connectedRegion(mask, openvdb::Coord(300)).voxelCount(), 0u) << "a seed outside the mask";
    EXPECT_EQ(regionSizes(mask).size(), 2u);
}

}  // namespace
}  // namespace sculpt
