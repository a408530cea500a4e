// SPDX-License-Identifier: Apache-2.0
#include "core/field/csg_combine.h"
#include "core/local/sphere_stamp.h"
#include "core/mesh/surface_statistics.h"
#include "core/primitives/analytic_shapes.h"
#include "tests/support/mesh_checks.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sculpt {
namespace {

void expectAgreesWithWeldedMesh(const IncrementalMesher& mesher, const SurfaceStatistics& stats, std::size_t shells)
{
    const TriangleMesh welded = mesher.weldedMesh();
    const test::MeshTopology topo = test::meshTopology(welded);
    ASSERT_TRUE(topo.closedManifold());
    EXPECT_EQ(stats.triangles(), welded.triangles.size());
    EXPECT_NEAR(stats.volume(), test::meshVolume(welded), 1e-9 * std::abs(stats.volume()));
    EXPECT_NEAR(stats.area(), test::meshArea(welded), 1e-9 * stats.area());
    const SurfaceTopology t = stats.topology(mesher);
    EXPECT_EQ(std::int64_t(t.vertices), topo.vertices);
    EXPECT_EQ(t.euler, topo.eulerCharacteristic());
    EXPECT_EQ(t.shells, shells);
}

TEST(SurfaceStatistics, SumsOfBlocksEqualTheWeldedMeshsMeasures)
{
    const FieldImage torus = makeTorus(20.0, 7.0, 0.5);
    IncrementalMesher mesher;
    mesher.rebuild(torus);
    SurfaceStatistics stats;
    stats.update(mesher);
    expectAgreesWithWeldedMesh(mesher, stats, 1);
    EXPECT_EQ(stats.topology(mesher).euler, 0);
    EXPECT_NEAR(stats.volume(), 2.0 * M_PI * M_PI * 20.0 * 49.0, 0.01 * stats.volume());
}

TEST(SurfaceStatistics, FollowsEditsBlockByBlockAndCountsShells)
{
    FieldImage field = makeSphere(12.0, 0.5);
    IncrementalMesher mesher;
    mesher.rebuild(field);
    SurfaceStatistics stats;
    stats.update(mesher);
    // A separate ball beside the sphere: a second shell, found across the blocks it spans.
    const FieldImage ball =
        rasterizeSdf({[](const openvdb::Vec3d& p) { return (p - openvdb::Vec3d(25, 3, 0)).length() - 6.0; },
                      openvdb::BBoxd(openvdb::Vec3d(19, -3, -6), openvdb::Vec3d(31, 9, 6)), 4 * M_PI * 36, "ball"},
                     0.5);
    mesher.update(field, combine(field, ball, CsgOperation::Union));
    stats.update(mesher);
    expectAgreesWithWeldedMesh(mesher, stats, 2);
    EXPECT_EQ(stats.topology(mesher).euler, 4);
    // A carve through the middle of the sphere's side: still one shell each, volume falls.
    const double volume = stats.volume();
    mesher.update(field, stampSphere(field, openvdb::Vec3d(0, 12, 0), 4.0, CsgMode::Carve));
    stats.update(mesher);
    EXPECT_LT(stats.volume(), volume);
    expectAgreesWithWeldedMesh(mesher, stats, 2);
}

}  // namespace
}  // namespace sculpt
