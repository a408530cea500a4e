// SPDX-License-Identifier: Apache-2.0
// Level-set motion against analytic laws: curvature flow, offsets, volume control, locality.

#include "core/base/errors.h"
#include "core/field/grid_checksum.h"
#include "core/local/sphere_stamp.h"
#include "core/mesh/field_measures.h"
#include "core/motion/level_set_evolution.h"
#include "core/motion/surface_flows.h"
#include "core/primitives/analytic_shapes.h"
#include "tests/support/surface_stats.h"

#include <gtest/gtest.h>
#include <openvdb/tools/LevelSetMeasure.h>

#include <cmath>

namespace sculpt {
namespace {

constexpr double kPi = 3.14159265358979323846;

double volumeRadius(const FieldImage& field)
{
    return std::cbrt(3.0 * openvdb::tools::levelSetVolume(field.grid()) / (4.0 * kPi));
}

TEST(LevelSetEvolution, MeanCurvatureFlowShrinksSphereAsR2Minus4BetaT)
{
    const double r0 = 20.0, beta = 1.0;
    FieldImage field = makeSphere(r0, 1.0);
    MotionTerms terms;
    terms.smooth = SmoothTerm{beta, std::nullopt};
    LevelSetEvolution evolution(field, terms);
    const double end = (r0 * r0 - 0.25 * r0 * r0) / (4.0 * beta);  // until r = r0 / 2
    for (double t = end / 5.0; t <= end + 1e-9; t += end / 5.0) {
        evolution.advance(t - evolution.time());
        const double expected = std::sqrt(r0 * r0 - 4.0 * beta * evolution.time());
        EXPECT_NEAR(volumeRadius(field), expected, 0.02 * expected) << "t = " << evolution.time();
    }
    EXPECT_NEAR(volumeRadius(field), r0 / 2.0, 0.02 * r0 / 2.0);
}

class OffsetSphere : public ::testing::TestWithParam<double> {};

TEST_P(OffsetSphere, ChangesRadiusByTheDistance)
{
    const double r = 20.0, h = 1.0, d = GetParam();
    FieldImage field = makeSphere(r, h);
    offset(field, d);
    const test::RadiusStats radius = test::surfaceRadius(field);
    EXPECT_NEAR(radius.mean, r + d, 0.1 * h);
    EXPECT_LT(radius.max - radius.min, 0.3 * h);  // still round
}

INSTANTIATE_TEST_SUITE_P(Distances, OffsetSphere, ::testing::Values(3.7, -4.2, 9.0), [](const auto& test) {
    return test.param > 0 ? "grow" + std::to_string(int(test.param)) : "shrink" + std::to_string(int(-test.param));
});

/// A sphere with six blobs stuck on it, redistanced as a sculpting session leaves it.
FieldImage bumpySphere()
{
    FieldImage field = makeSphere(16.0, 1.0);
    const openvdb::Vec3d directions[] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0.6, 0.6, -0.5}};
    for (auto d : directions) {
        d.normalize();
        stampSphere(field, d * 17.0, 5.0, CsgMode::Add);
    }
    LevelSetEvolution(field, MotionTerms{}).redistance();
    return field;
}

TEST(LevelSetOperations, SmoothingLosesVolumeWithoutControl)
{
    FieldImage field = bumpySphere();
    const double v0 = openvdb::tools::levelSetVolume(field.grid());
    const double k0 = test::curvatureVariance(field);
    smooth(field, 50, false);
    EXPECT_LT(openvdb::tools::levelSetVolume(field.grid()), 0.98 * v0);
    EXPECT_LT(test::curvatureVariance(field), 0.8 * k0);
}

TEST(LevelSetOperations, SmoothingKeepsVolumeWithControl)
{
    FieldImage field = bumpySphere();
    const double v0 = openvdb::tools::levelSetVolume(field.grid());
    const double k0 = test::curvatureVariance(field);
    smooth(field, 50, true);
    EXPECT_NEAR(openvdb::tools::levelSetVolume(field.grid()), v0, 0.005 * v0);
    EXPECT_LT(test::curvatureVariance(field), 0.8 * k0);
}

/// Keep-volume smoothing holds the mesh's volume (what `info`, the export and a printer see),
/// also where sharp edges make a band estimate differ from it (a box drifted +0.56% before).
class KeepVolumeSmoothing : public ::testing::TestWithParam<std::tuple<const char*, int>> {};

TEST_P(KeepVolumeSmoothing, HoldsTheMeshVolumeWithinATenthOfAPercent)
{
    const auto [shape, iterations] = GetParam();
    FieldImage field = std::string(shape) == "box" ? makeBox(0.9, 0.05) : makeTorus(1.0, 0.4, 0.02);
    const double before = measureField(field).volume;
    const double k0 = test::curvatureVariance(field);
    smooth(field, iterations, true);
    const FieldMeasures after = measureField(field);
    EXPECT_NEAR(after.volume, before, 0.001 * before) << shape << ", " << iterations << " iterations";
    EXPECT_NEAR(meshVolumeArea(field).volume, after.volume, 1e-9 * before);  // the same measure
    if (std::string(shape) == "box") {
        EXPECT_LT(test::curvatureVariance(field), k0);  // it did smooth
    }
}

INSTANTIATE_TEST_SUITE_P(Shapes, KeepVolumeSmoothing,
                         ::testing::Combine(::testing::Values("box", "torus"), ::testing::Values(30, 200)));

TEST(LevelSetEvolution, RejectsBadCoefficients)
{
    FieldImage field = makeSphere(8.0, 1.0);
    MotionTerms terms;
    terms.smooth = SmoothTerm{-1.0, std::nullopt};
    EXPECT_THROW(LevelSetEvolution(field, terms), InputError);
    EXPECT_THROW(smooth(field, -3), InputError);
    EXPECT_THROW(offset(field, std::nan("")), InputError);
}

TEST(LevelSetEvolution, SettlingTheVolumeMarksEveryLeafItMovedDirty)
{
    FieldImage field = makeSphere(10.0, 0.5);
    const double target = 4.0 / 3.0 * kPi * 11.0 * 11.0 * 11.0;  // a radius 1 larger: every voxel moves
    MotionTerms terms;
    terms.volume = VolumeTerm{target, 1.0};
    LevelSetEvolution evolution(field, terms);
    field.takeDirtyRegion();
    evolution.settleVolume();
    EXPECT_GT(volumeRadius(field), 10.5);
    // The mesher re-meshes only what is reported: a uniform offset must report every leaf.
    EXPECT_EQ(field.takeDirtyRegion().leafCount(), field.allLeaves().leafCount());
}

}  // namespace
}  // namespace sculpt
