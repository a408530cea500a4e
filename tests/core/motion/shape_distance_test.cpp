// SPDX-License-Identifier: Apache-2.0
// Distances between shapes beyond their narrow bands, and where a shape is resolvable.

#include "core/motion/shape_distance.h"
#include "core/motion/wide_distance.h"
#include "core/primitives/analytic_shapes.h"

#include <gtest/gtest.h>
#include <openvdb/tools/LevelSetSphere.h>

namespace sculpt {
namespace {

TEST(WideDistance, ReadsTheTrueDistanceFarBeyondTheBandOverTheCoveredSurface)
{
    // A ball of radius 8 and, 40 voxels away, the surface the distance must cover.
    const FieldImage ball = makeSphere(8.0, 1.0);
    const FieldImage cover(openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(4.0f, {48.0f, 0.0f, 0.0f}, 1.0f));
    const WideDistance distance(ball.gridPtr(), cover.grid());
    WideDistance::Sampler sampler(distance);
    for (const double x : {-6.0, 0.0, 5.0, 7.5, 20.0, 44.0, 52.0}) {
        const openvdb::Vec3d p(x, 0.0, 0.0);
        EXPECT_NEAR(sampler.at(p), std::abs(x) - 8.0, std::abs(std::abs(x) - 8.0) < 3.0 ? 0.05 : 0.5) << "x = " << x;
    }
    // A narrow band alone saturates there.
    EXPECT_NEAR(surfaceToField(cover.grid(), ball.grid()).maxWorld, 3.0, 1e-6);
    EXPECT_NEAR(surfaceToField(cover.grid(), distance).maxWorld, 44.0, 0.5);  // the cover's far side, x = 52
}

TEST(ShapeDistance, TwoSidedDistanceOfConcentricBallsIsTheirRadiiApart)
{
    const FieldImage inner = makeSphere(10.0, 1.0), outer = makeSphere(16.0, 1.0);
    const WideDistance innerDistance(inner.gridPtr(), outer.grid()), outerDistance(outer.gridPtr(), inner.grid());
    const ShapeDistance d = twoSidedDistance(inner.grid(), innerDistance, outer.grid(), outerDistance);
    EXPECT_NEAR(d.maxWorld, 6.0, 0.5);
    EXPECT_NEAR(d.meanWorld, 6.0, 0.5);
    EXPECT_DOUBLE_EQ(d.resolvedFraction, 1.0);
    EXPECT_DOUBLE_EQ(d.maxResolvedWorld, d.maxWorld);
    // With only the inner ball's band, the direction from the outer surface saturates at 3 voxels.
    EXPECT_NEAR(twoSidedDistance(outer.grid(), inner.grid(), innerDistance).maxWorld, 6.0, 0.5);
    EXPECT_NEAR(surfaceToField(inner.grid(), outer.grid()).maxWorld, 3.0, 1e-6);
}

TEST(ShapeDistance, ThinPartsAreNotResolvableAndThickOnesAre)
{
    const FieldImage thin = makeTorus(12.0, 1.0, 1.0), thick = makeTorus(12.0, 5.0, 1.0);
    EXPECT_LT(surfaceToField(thin.grid(), thin.grid()).resolvedFraction, 0.05);
    EXPECT_DOUBLE_EQ(surfaceToField(thick.grid(), thick.grid()).resolvedFraction, 1.0);
    EXPECT_LT(surfaceToField(thick.grid(), thick.grid()).maxWorld, 0.05);
}

}  // namespace
}  // namespace sculpt
