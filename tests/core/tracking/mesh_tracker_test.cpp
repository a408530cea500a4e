// The tracked mesh on fields that do not move: it settles (drift under a hundredth of a voxel a
// step), stays on the surface, closed and 2-manifold with the marching-cubes mesh's topology,
// its triangles well shaped and its edges within [e, 2e], bit for bit the same on 1 or 2 threads.

#include "core/mesh/incremental_mesher.h"
#include "core/primitives/analytic_shapes.h"
#include "core/tracking/mesh_tracker.h"
#include "core/tracking/surface_projection.h"
#include "tests/support/mesh_checks.h"

#include <gtest/gtest.h>
#include <openvdb/tools/Interpolation.h>
#include <tbb/global_control.h>

#include <map>

namespace sculpt {
namespace {

using openvdb::Vec3d;

/// Worst |phi| over the vertices, read by OpenVDB's trilinear sampler, in voxels.
double worstPhiVoxels(const TrackedMesh& mesh, const FieldImage& field)
{
    const openvdb::tools::GridSampler<openvdb::FloatGrid, openvdb::tools::BoxSampler> sampler(field.grid());
    double worst = 0.0;
    for (const Vec3d& p : mesh.positions) worst = std::max(worst, std::abs(double(sampler.wsSample(p))));
    return worst / field.voxelSize();
}

struct Quality {
    double belowTwentyDegrees = 0.0;  // share of triangles
    double smallestAngle = 180.0;     // degrees
    double shortestEdge = 1e30, longestEdge = 0.0;
};

Quality qualityOf(const TrackedMesh& mesh)
{
    Quality q;
    std::size_t below = 0;
    for (const auto& t : mesh.triangles) {
        const double angle = smallestAngleDegrees(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]);
        q.smallestAngle = std::min(q.smallestAngle, angle);
        below += angle < 20.0;
        for (int k = 0; k < 3; ++k) {
            const double length = (mesh.positions[t[k]] - mesh.positions[t[(k + 1) % 3]]).length();
            q.shortestEdge = std::min(q.shortestEdge, length);
            q.longestEdge = std::max(q.longestEdge, length);
        }
    }
    q.belowTwentyDegrees = double(below) / double(mesh.triangles.size());
    return q;
}

/// Largest move of a vertex (by id) between two meshes, for the ids in both.
double largestMove(const TrackedMesh& before, const TrackedMesh& after)
{
    std::map<std::uint32_t, Vec3d> was;
    for (std::size_t v = 0; v < before.ids.size(); ++v) was[before.ids[v]] = before.positions[v];
    double largest = 0.0;
    for (std::size_t v = 0; v < after.ids.size(); ++v) {
        const auto it = was.find(after.ids[v]);
        if (it != was.end()) largest = std::max(largest, (after.positions[v] - it->second).length());
    }
    return largest;
}

void expectSettledAndWellShaped(const FieldImage& field)
{
    const double h = field.voxelSize();
    MeshTracker tracker(field);
    const test::MeshTopology mc = test::meshTopology(meshLevelSet(field));
    TrackedMesh previous = tracker.mesh();
    double lastMove = 0.0;
    for (int step = 0; step < 100; ++step) {
        const TrackingStep report = tracker.step(field);
        EXPECT_TRUE(report.quasiCritical.empty()) << "step " << step;
        EXPECT_LT(worstPhiVoxels(tracker.mesh(), field), 0.05) << "step " << step;
        lastMove = largestMove(previous, tracker.mesh()) / h;
        previous = tracker.mesh();
    }
    EXPECT_LT(lastMove, 0.01) << "voxels the farthest vertex moved in the last step";
    const TriangleMesh mesh = tracker.mesh().triangleMesh();
    const test::MeshTopology topology = test::meshTopology(mesh);
    EXPECT_TRUE(topology.closedManifold());
    EXPECT_EQ(topology.eulerCharacteristic(), mc.eulerCharacteristic());
    EXPECT_EQ(test::shellTriangleCounts(mesh).size(), 1u);
    const Quality q = qualityOf(tracker.mesh());
    EXPECT_LT(q.belowTwentyDegrees, 0.01);
    EXPECT_GT(q.smallestAngle, 10.0);
    const double e = tracker.edgeLength();
    EXPECT_GE(q.shortestEdge, e * 0.99) << "e = " << e;
    EXPECT_LE(q.longestEdge, 2.0 * e * 1.01) << "e = " << e;
}

TEST(MeshTracker, OnAStillSphereSettlesOnTheSurfaceWithWellShapedTriangles)
{
    expectSettledAndWellShaped(makeSphere(12.0, 0.5));
}

TEST(MeshTracker, OnAStillTorusSettlesOnTheSurfaceWithWellShapedTriangles)
{
    expectSettledAndWellShaped(makeTorus(10.0, 4.0, 0.5));
}

TEST(MeshTracker, IsBitIdenticalOnOneAndTwoThreads)
{
    const FieldImage field = makeTorus(10.0, 4.0, 0.5);
    const auto run = [&](int threads) {
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
        MeshTracker tracker(field);
        for (int step = 0; step < 10; ++step) tracker.step(field);
        return tracker.mesh();
    };
    const TrackedMesh one = run(1), two = run(2);
    EXPECT_EQ(one.ids, two.ids);
    EXPECT_EQ(one.triangles, two.triangles);
    ASSERT_EQ(one.positions.size(), two.positions.size());
    for (std::size_t v = 0; v < one.positions.size(); ++v) ASSERT_EQ(one.positions[v], two.positions[v]) << v;
}

TEST(SurfaceProjection, BringsPointsNearASphereOntoItAndFlagsTheCentre)
{
    const double r = 10.0, h = 0.5;
    const FieldImage field = makeSphere(r, h);
    const FieldProbe probe(field.grid());
    for (const Vec3d direction : {Vec3d(1, 0, 0), Vec3d(1, 2, 3).unit(), Vec3d(-0.3, 0.9, -0.1).unit()})
        for (const double offset : {-0.9, -0.3, 0.2, 0.8}) {
            const Projection p = projectOntoSurface(probe, direction * (r + offset));
            EXPECT_FALSE(p.quasiCritical);
            EXPECT_NEAR(p.position.length(), r, 0.05 * h) << direction << " " << offset;
            EXPECT_NEAR(p.gradient.unit().dot(direction), 1.0, 1e-3);
        }
    const Projection centre = projectOntoSurface(probe, Vec3d(0.0));  // flat: no band there
    EXPECT_TRUE(centre.quasiCritical);
    EXPECT_EQ(centre.position, Vec3d(0.0));
}

}  // namespace
}  // namespace sculpt
