// SPDX-License-Identifier: Apache-2.0
#include "core/local/speck_removal.h"
#include "core/primitives/analytic_shapes.h"

#include <gtest/gtest.h>

namespace sculpt {
namespace {

using openvdb::Coord;

/// The sphere of radius 10 at voxel 1 with `values` written into its band as active voxels.
FieldImage sphereWith(const std::vector<std::pair<Coord, float>>& values)
{
    FieldImage field = makeSphere(10.0, 1.0);
    auto acc = field.mutableGrid().getAccessor();
    for (const auto& [c, v] : values) acc.setValueOn(c, v);
    return field;
}

const Capsule kEverywhere{openvdb::Vec3d(0.0), openvdb::Vec3d(0.0), 100.0};

std::size_t removeSpecksIn(FieldImage& field, const Capsule& region = kEverywhere)
{
    return removeSpecks(field.mutableGrid(), region, field.allLeaves().leafOrigins());
}

TEST(SpeckRemoval, FlipsAnIslandOfInsideInTheOutside)
{
    // Two voxels just outside the sphere (x = 12, 13: phi > 0 there) made inside: a tiny shell.
    FieldImage field = sphereWith({{Coord(12, 0, 0), -0.2f}, {Coord(12, 1, 0), -0.1f}});
    EXPECT_EQ(removeSpecksIn(field), 2u);
    const auto acc = field.grid().getConstAccessor();
    EXPECT_FLOAT_EQ(acc.getValue(Coord(12, 0, 0)), 0.2f);
    EXPECT_FLOAT_EQ(acc.getValue(Coord(12, 1, 0)), 0.1f);
    EXPECT_EQ(removeSpecksIn(field), 0u);  // nothing left to remove
}

TEST(SpeckRemoval, FlipsABubbleOfOutsideInTheInside)
{
    FieldImage field = sphereWith({{Coord(0, 0, 8), 0.3f}});  // phi(0,0,8) = -2 before: inside
    EXPECT_EQ(removeSpecksIn(field), 1u);
    EXPECT_FLOAT_EQ(field.grid().getConstAccessor().getValue(Coord(0, 0, 8)), -0.3f);
}

TEST(SpeckRemoval, TheWholeFieldPassFindsSpecksAnywhere)
{
    FieldImage field = sphereWith({{Coord(12, 0, 0), -0.2f}, {Coord(0, -12, 5), -0.3f}, {Coord(0, 0, -8), 0.4f}});
    EXPECT_EQ(removeSpecks(field), 3u);
    EXPECT_EQ(removeSpecks(field), 0u);
}

TEST(SpeckRemoval, KeepsTheSurfaceFeaturesAndWhatLiesBeyondTheRegion)
{
    // A group of nine voxels is a feature; a speck reaching past the region cannot be fixed here.
    std::vector<std::pair<Coord, float>> nine;
    for (int i = 0; i < 9; ++i) nine.push_back({Coord(0, 0, 12) + Coord(i % 3, i / 3, 0), -0.1f});
    FieldImage field = sphereWith(nine);
    EXPECT_EQ(removeSpecksIn(field), 0u);
    FieldImage beyond = sphereWith({{Coord(12, 0, 0), -0.2f}});
    const Capsule small{openvdb::Vec3d(0.0), openvdb::Vec3d(0.0), 11.5};
    EXPECT_EQ(removeSpecksIn(beyond, small), 0u);
    // The sphere itself (one shell, thousands of voxels) is never touched.
    FieldImage sphere = makeSphere(10.0, 1.0);
    EXPECT_EQ(removeSpecksIn(sphere), 0u);
}

}  // namespace
}  // namespace sculpt
