// SPDX-License-Identifier: Apache-2.0
// A plane's cut of the solid, from the field: the clay ball's cap through its centre is pi r^2
// within 0.5% (and its outline 2 pi r), an off-centre or tilted cut the circle's area there, a
// box's cut its square, and a plane missing the solid cuts nothing.

#include "core/primitives/analytic_shapes.h"
#include "core/solids/cross_section.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sculpt {
namespace {

using openvdb::Vec3d;

double outlineLength(const CrossSection& section)
{
    double length = 0.0;
    for (const auto& segment : section.outline) length += (segment[1] - segment[0]).length();
    return length;
}

TEST(CrossSection, TheBallsCapThroughItsCentreIsPiRSquared)
{
    const double r = 50.0;
    const FieldImage ball = makeSphere(r, 0.5);
    const CrossSection centre = crossSection(ball, {Vec3d(0.0), Vec3d(0, 0, 1)});
    EXPECT_NEAR(centre.area, M_PI * r * r, 0.005 * M_PI * r * r);
    EXPECT_NEAR(outlineLength(centre), 2.0 * M_PI * r, 0.005 * 2.0 * M_PI * r);
    // The triangles hold that area too, each facing along the normal.
    double triangles = 0.0;
    const TriangleMesh& mesh = centre.region;
    for (const auto& t : mesh.triangles) {
        const Vec3d a(mesh.positions[t[0]].data()), b(mesh.positions[t[1]].data()), c(mesh.positions[t[2]].data());
        const Vec3d n = (b - a).cross(c - a);
        EXPECT_GE(n.z(), 0.0) << "counter-clockwise seen from the normal's side";
        triangles += 0.5 * n.length();
    }
    EXPECT_NEAR(triangles, centre.area, 1e-3 * centre.area);

    const double z = 30.0, rz = std::sqrt(r * r - z * z);
    EXPECT_NEAR(crossSection(ball, {Vec3d(7.0, -3.0, z), Vec3d(0, 0, 1)}).area, M_PI * rz * rz, 0.005 * M_PI * rz * rz);
    const Vec3d tilted = Vec3d(1.0, 2.0, -2.0).unit();
    EXPECT_NEAR(crossSection(ball, {tilted * z, tilted}).area, M_PI * rz * rz, 0.005 * M_PI * rz * rz);
    EXPECT_EQ(crossSection(ball, {Vec3d(0, 0, 2.0 * r), Vec3d(0, 0, 1)}).area, 0.0);
    EXPECT_TRUE(crossSection(ball, {Vec3d(0, 0, 2.0 * r), Vec3d(0, 0, 1)}).region.triangles.empty());
}

TEST(CrossSection, ABoxCutAcrossIsItsSquare)
{
    const FieldImage box = makeBox(20.0, 0.5);
    EXPECT_NEAR(crossSection(box, {Vec3d(0, 5.0, 0), Vec3d(0, 1, 0)}).area, 40.0 * 40.0, 0.005 * 1600.0);
}

}  // namespace
}  // namespace sculpt
