// SPDX-License-Identifier: Apache-2.0
// Starting shapes against their analytic volume, area and topology, and against OpenVDB's own
// sphere builder.

#include "core/base/errors.h"
#include "core/mesh/field_measures.h"
#include "core/primitives/analytic_shapes.h"

#include <gtest/gtest.h>
#include <openvdb/tools/LevelSetSphere.h>

#include <cmath>

namespace sculpt {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Expected {
    double volume, area;
    int euler;
};

void expectMeasures(const FieldImage& field, const Expected& e, double areaTolerance = 0.01,
                    double volumeTolerance = 0.01)
{
    const FieldMeasures m = measureField(field);
    EXPECT_NEAR(m.volume, e.volume, volumeTolerance * e.volume);
    EXPECT_NEAR(m.area, e.area, areaTolerance * e.area);
    EXPECT_EQ(m.eulerCharacteristic, e.euler);
    EXPECT_EQ(m.components, 1);
    EXPECT_GT(m.activeVoxels, 0u);
    EXPECT_GT(m.memoryBytes, m.activeVoxels * sizeof(float));
}

TEST(AnalyticShapes, SphereMatchesAnalyticMeasures)
{
    const double r = 10.0, h = 1.0;  // 20 voxels across
    expectMeasures(makeSphere(r, h), {4.0 / 3.0 * kPi * r * r * r, 4.0 * kPi * r * r, 2});
}

// Measures are those of the welded mesh, and marching cubes cuts a box's 90-degree edges: the
// area loses about 0.3 voxel per voxel of edge, a relative error of ~1.2 / n for a box n voxels
// across (6% at n = 20, 1.2% at n = 100), the volume much less. First-order convergence.
TEST(AnalyticShapes, BoxMatchesAnalyticVolume)
{
    const double a = 5.0, h = 0.5;  // 20 voxels across
    expectMeasures(makeBox(a, h), {8.0 * a * a * a, 24.0 * a * a, 2}, 0.07, 0.02);
}

TEST(AnalyticShapes, BoxAreaConvergesAtFirstOrder)
{
    const double a = 5.0, area = 24.0 * a * a;
    const double coarse = std::abs(measureField(makeBox(a, 0.5)).area - area) / area;  // 20 voxels
    const double fine = std::abs(measureField(makeBox(a, 0.1)).area - area) / area;    // 100 voxels
    EXPECT_LT(fine, 0.015);
    EXPECT_LT(fine, 0.3 * coarse);
    expectMeasures(makeBox(a, 0.1), {8.0 * a * a * a, area, 2}, 0.015);
}

TEST(AnalyticShapes, TorusMatchesAnalyticMeasures)
{
    const double R = 30.0, r = 10.0, h = 1.0;  // tube 20 voxels across
    expectMeasures(makeTorus(R, r, h), {2.0 * kPi * kPi * R * r * r, 4.0 * kPi * kPi * R * r, 0});
}

TEST(AnalyticShapes, BoundingBoxIsTheSurfaceBox)
{
    const FieldMeasures m = measureField(makeTorus(12.0, 4.0, 0.5));
    for (int axis = 0; axis < 2; ++axis) {
        EXPECT_NEAR(m.bboxMin[axis], -16.0, 0.05);
        EXPECT_NEAR(m.bboxMax[axis], 16.0, 0.05);
    }
    EXPECT_NEAR(m.bboxMin.z(), -4.0, 0.05);
    EXPECT_NEAR(m.bboxMax.z(), 4.0, 0.05);
}

TEST(AnalyticShapes, SphereAgreesWithOpenVdbSphere)
{
    const float r = 12.0f, h = 0.5f;
    const FieldImage ours = makeSphere(r, h);
    const auto theirs = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(
        r, openvdb::Vec3f(0.0f), h, float(FieldImage::kDefaultHalfWidthVoxels));
    // Same band: every voxel active in one is active in the other, with the same distance.
    auto acc = theirs->getConstAccessor();
    std::size_t compared = 0;
    for (auto it = ours.grid().cbeginValueOn(); it; ++it) {
        const float d = *it;
        if (std::abs(d) > 2.5f * h) continue;  // band edges may differ by rounding
        ASSERT_TRUE(acc.isValueOn(it.getCoord())) << it.getCoord();
        ASSERT_NEAR(acc.getValue(it.getCoord()), d, 1e-4f * h) << it.getCoord();
        ++compared;
    }
    EXPECT_GT(compared, 10000u);
}

TEST(AnalyticShapes, InteriorIsNegativeOutsideBand)
{
    const FieldImage sphere = makeSphere(20.0, 1.0);
    auto acc = sphere.grid().getConstAccessor();
    EXPECT_LT(acc.getValue(openvdb::Coord(0, 0, 0)), 0.0f);
    EXPECT_GT(acc.getValue(openvdb::Coord(40, 0, 0)), 0.0f);
    EXPECT_FALSE(acc.isValueOn(openvdb::Coord(0, 0, 0)));
    EXPECT_DOUBLE_EQ(sphere.halfWidthVoxels(), FieldImage::kDefaultHalfWidthVoxels);
}

TEST(AnalyticShapes, RejectsBadParameters)
{
    EXPECT_THROW(makeSphere(-1.0, 1.0), InputError);
    EXPECT_THROW(makeSphere(10.0, 0.0), InputError);
    EXPECT_THROW(makeSphere(10.0, std::nan("")), InputError);
    EXPECT_THROW(makeSphere(0.5, 1.0), InputError);  // less than two voxels across
    EXPECT_THROW(makeTorus(10.0, 10.0, 1.0), InputError);
    EXPECT_THROW(makeBox(std::numeric_limits<double>::infinity(), 1.0), InputError);
}

TEST(AnalyticShapes, RefusesShapesLargerThanMemoryBeforeAllocating)
{
    try {
        makeSphere(1.0e5, 0.01);  // ~10^16 band voxels
        FAIL() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("memory"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace sculpt
