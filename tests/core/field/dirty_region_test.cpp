// SPDX-License-Identifier: Apache-2.0
#include "core/field/dirty_region.h"
#include "core/field/field_image.h"
#include "core/primitives/analytic_shapes.h"

#include <gtest/gtest.h>

namespace sculpt {
namespace {

TEST(DirtyRegion, VoxelsMapToTheirLeafOrigin)
{
    EXPECT_EQ(DirtyRegion::leafOriginOf({0, 7, 8}), openvdb::Coord(0, 0, 8));
    EXPECT_EQ(DirtyRegion::leafOriginOf({-1, -8, -9}), openvdb::Coord(-8, -8, -16));
}

TEST(DirtyRegion, DeduplicatesAndSorts)
{
    DirtyRegion region;
    region.addVoxel({9, 0, 0});
    region.addVoxel({-3, 0, 0});
    region.addVoxel({10, 1, 2});
    ASSERT_EQ(region.leafCount(), 2u);
    const auto origins = region.leafOrigins();
    EXPECT_EQ(origins[0], openvdb::Coord(-8, 0, 0));
    EXPECT_EQ(origins[1], openvdb::Coord(8, 0, 0));
    EXPECT_TRUE(region.containsLeaf({8, 0, 0}));
    EXPECT_FALSE(region.containsLeaf({16, 0, 0}));
}

TEST(DirtyRegion, FieldImageAccumulatesUntilTaken)
{
    FieldImage field = makeSphere(8.0, 1.0);
    EXPECT_TRUE(field.dirtyRegion().empty());
    DirtyRegion a, b;
    a.addVoxel({1, 1, 1});
    b.addVoxel({100, 1, 1});
    field.markDirty(a);
    field.markDirty(b);
    EXPECT_EQ(field.dirtyRegion().leafCount(), 2u);
    const DirtyRegion taken = field.takeDirtyRegion();
    EXPECT_EQ(taken.leafCount(), 2u);
    EXPECT_TRUE(field.dirtyRegion().empty());
}

}  // namespace
}  // namespace sculpt
