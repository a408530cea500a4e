// SPDX-License-Identifier: Apache-2.0
// The tracked mesh on fields that do not move: it settles (drift under a hundredth of a voxel a
// step), stays on the surface, closed and 2-manifold with the marching-cubes mesh's topology,
// its triangles well shaped and its edges within [e, 2e], bit for bit the same on 1 or 2 threads.

#include "core/brushes/brush.h"
#include "core/local/falloff.h"
#include "core/mesh/incremental_mesher.h"
#include "core/motion/morph.h"
#include "core/primitives/analytic_shapes.h"
#include "core/primitives/sdf_rasterizer.h"
#include "core/tracking/mesh_adjacency.h"
#include "core/tracking/mesh_tracker.h"
#include "core/tracking/surface_projection.h"
#include "core/tracking/tracked_mesh_quality.h"
#include "tests/support/grid_builders.h"
#include "tests/support/mesh_checks.h"

#include <gtest/gtest.h>
#include <openvdb/tools/Interpolation.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <functional>
#include <map>
#include <optional>
#include <set>

namespace sculpt {
namespace {

using openvdb::Vec3d;

/// Worst |phi| over the vertices, read by OpenVDB's trilinear sampler, in voxels; quasi-critical
/// points (left where they were, by design) are not counted.
double worstPhiVoxels(const TrackedMesh& mesh, const FieldImage& field,
                      const std::vector<QuasiCriticalPoint>& flagged = {})
{
    std::vector<std::uint32_t> skip;
    for (const QuasiCriticalPoint& q : flagged) skip.push_back(q.vertexId);
    std::sort(skip.begin(), skip.end());
    const openvdb::tools::GridSampler<openvdb::FloatGrid, openvdb::tools::BoxSampler> sampler(field.grid());
    double worst = 0.0;
    for (std::size_t v = 0; v < mesh.positions.size(); ++v)
        if (!std::binary_search(skip.begin(), skip.end(), mesh.ids[v]))
            worst = std::max(worst, std::abs(double(sampler.wsSample(mesh.positions[v]))));
    return worst / field.voxelSize();
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

/// A closed 2-manifold of the marching-cubes mesh's topology, triangles and edges as the tracker keeps them.
void expectWellShaped(const TrackedMesh& tracked, const FieldImage& field, double e, double edgeSlack = 0.01)
{
    const TriangleMesh mesh = tracked.triangleMesh();
    const test::MeshTopology topology = test::meshTopology(mesh);
    EXPECT_TRUE(topology.closedManifold());
    const TriangleMesh mc = meshLevelSet(field);
    EXPECT_EQ(topology.eulerCharacteristic(), test::meshTopology(mc).eulerCharacteristic());
    EXPECT_EQ(test::shellTriangleCounts(mesh).size(), test::shellTriangleCounts(mc).size());
    const TrackedMeshQuality q = measureQuality(tracked);
    EXPECT_LT(q.belowTwentyDegrees, 0.01);
    EXPECT_GT(q.smallestAngle, 10.0);
    EXPECT_GE(q.shortestEdge, e * (1.0 - edgeSlack)) << "e = " << e;
    EXPECT_LE(q.longestEdge, 2.0 * e * (1.0 + edgeSlack)) << "e = " << e;
}

void expectSettledAndWellShaped(const FieldImage& field)
{
    const double h = field.voxelSize();
    MeshTracker tracker(field);
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
    expectWellShaped(tracker.mesh(), field, tracker.edgeLength());
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

/// What tracking a morph of `source` into `target` went through.
struct TrackedMorph {
    std::vector<TrackedMesh> frames;
    std::optional<FieldImage> last;
    double edge = 0.0, worstPhi = 0.0;
    std::size_t steps = 0, changes = 0, flagged = 0, reseeds = 0;
};

TrackedMorph trackMorph(const FieldImage& source, const FieldImage& target, int frames)
{
    MorphOptions options;
    options.frames = frames;
    std::optional<MeshTracker> tracker;
    TrackedMorph run;
    const MorphSummary summary = morph(
        source, target, options,
        [&](const MorphFrame& frame) {
            if (!tracker) tracker.emplace(frame.field);
            run.frames.push_back(tracker->mesh());
            run.last.emplace(frame.field.deepCopy());
        },
        {},
        [&](const FieldImage& field) {
            const TrackingStep s = tracker->step(field);
            run.changes += s.splits + s.collapses;
            run.flagged += s.quasiCritical.size();
            run.reseeds += s.reseeded;
            run.worstPhi = std::max(run.worstPhi, worstPhiVoxels(tracker->mesh(), field));
            ++run.steps;
        });
    EXPECT_TRUE(summary.converged);
    run.edge = tracker->edgeLength();
    return run;
}

// A sphere moved by 3 voxels in 12 steps, the tracker told the displacement (a rigid move): no
// edge changes length, so vertices and triangles stay the same and move with the sphere.
TEST(MeshTracker, FollowsARigidMoveWithConstantConnectivity)
{
    const double h = 0.5;
    const FieldImage ball = makeSphere(12.0, h);
    MeshTracker tracker(ball);
    const TrackedMesh first = tracker.mesh();
    const Vec3d step(0.25 * h, 0.0, 0.0);
    double worstPhi = 0.0;
    for (int k = 1; k <= 12; ++k) {
        const FieldImage moved = test::translated(ball, step * k);
        const TrackingStep s = tracker.step(moved, [&](const Vec3d&) { return step; });
        EXPECT_EQ(s.splits + s.collapses, 0u) << "step " << k;
        EXPECT_TRUE(s.quasiCritical.empty());
        EXPECT_FALSE(s.reseeded);
        worstPhi = std::max(worstPhi, worstPhiVoxels(tracker.mesh(), moved));
    }
    EXPECT_LT(worstPhi, 0.05);
    const TrackedMesh& last = tracker.mesh();
    EXPECT_EQ(last.ids, first.ids);
    EXPECT_EQ(last.triangles, first.triangles);
    double worstOffset = 0.0;  // from where the rigid move alone puts each vertex
    for (std::size_t v = 0; v < first.positions.size(); ++v)
        worstOffset = std::max(worstOffset, (last.positions[v] - (first.positions[v] + step * 12)).length());
    EXPECT_LT(worstOffset, 0.1 * h);  // the relaxation's own last settling
    expectWellShaped(last, test::translated(ball, step * 12), tracker.edgeLength());
}

// A sphere morphed into a box of the same volume (a quarter more area): the corners stretch and
// the faces shrink by up to 3 voxels. The edges that the seed's irregular valences leave nearest e
// and 2e are held in range by the triangles around them (edge_hold.h), so vertices and triangles
// stay the same through the whole morph, on the surface and well shaped.
TEST(MeshTracker, FollowsASphereMorphingIntoABoxWithConstantConnectivity)
{
    const double h = 0.5, r = 12.0;
    const TrackedMorph run = trackMorph(makeSphere(r, h), makeBox(r * std::sqrt(M_PI / 6.0), h), 4);
    ASSERT_EQ(run.frames.size(), 4u);
    EXPECT_EQ(run.flagged, 0u);
    EXPECT_EQ(run.reseeds, 0u);
    EXPECT_LT(run.worstPhi, 0.05);
    EXPECT_EQ(run.changes, 0u);
    const TrackedMesh &first = run.frames.front(), &last = run.frames.back();
    EXPECT_EQ(last.ids, first.ids);
    EXPECT_EQ(last.triangles, first.triangles);
    expectWellShaped(last, *run.last, run.edge);
}

// A grab stroke pulling the side of a ball out by 3 voxels in 12 stamps, the tracker told the
// brush's own displacement (its falloff around each sub-step's ball): the relaxation spreads the
// bump's stretch, so vertices and triangles stay the same, on the surface and well shaped.
TEST(MeshTracker, FollowsAGrabStrokeWithConstantConnectivity)
{
    const double r = 12.0, h = 0.5;
    FieldImage field = makeSphere(r, h);
    MeshTracker tracker(field);
    const TrackedMesh first = tracker.mesh();
    BrushSettings brush;
    brush.tool = BrushTool::Grab;
    brush.radiusWorld = 5.0;
    brush.strength = 1.0;
    const Vec3d step(0.25 * h, 0.0, 0.0);
    double worstPhi = 0.0;
    std::size_t changes = 0;
    for (int k = 0; k < 12; ++k) {
        BrushStamp stamp;
        stamp.previousWorld = Vec3d(r, 0.0, 0.0) + step * k;
        stamp.centreWorld = stamp.previousWorld + step;
        applyStamp(field, brush, stamp, nullptr);
        const FalloffBall ball{stamp.previousWorld, brush.radiusWorld, brush.falloff};  // one sub-step: under a voxel
        const TrackingStep s = tracker.step(field, [&](const Vec3d& p) { return step * ball.weightAt(p); });
        changes += s.splits + s.collapses;
        EXPECT_TRUE(s.quasiCritical.empty());
        EXPECT_EQ(s.surgery.kind, SurgeryKind::None);
        EXPECT_FALSE(s.reseeded);
        worstPhi = std::max(worstPhi, worstPhiVoxels(tracker.mesh(), field));
    }
    EXPECT_EQ(changes, 0u);
    EXPECT_EQ(tracker.mesh().ids, first.ids);
    EXPECT_EQ(tracker.mesh().triangles, first.triangles);
    EXPECT_LT(worstPhi, 0.05);
    expectWellShaped(tracker.mesh(), field, tracker.edgeLength());
}

/// The ground truth a tracker follows: the topology of the marching-cubes mesh's shells of at
/// least MeshTracker::kResolvableEdges e across (edge length `e`).
SurfaceTopology resolvableTopology(const FieldImage& field, double e)
{
    TrackedMesh mc = TrackedMesh::of(meshLevelSet(field));
    mc.dropShellsUnder(MeshTracker::kResolvableEdges * e);
    return surfaceTopology(mc.triangles, mc.positions.size());
}

/// What tracking a morph through topology events went through.
struct TopologyMorph {
    std::size_t reseeds = 0, surgeries = 0, mismatches = 0, steps = 0;
    double worstPhi = 0.0;  // voxels, unflagged vertices, every step
    std::vector<TrackedMesh> frames;
};

/// Tracks a morph of `source` into `target` in 3 frames, each frame checked well shaped.
TopologyMorph trackTopologyMorph(const FieldImage& source, const FieldImage& target)
{
    MorphOptions options;
    options.frames = 3;
    std::optional<MeshTracker> tracker;
    TopologyMorph run;
    morph(
        source, target, options,
        [&](const MorphFrame& frame) {
            if (!tracker) tracker.emplace(frame.field);
            run.frames.push_back(tracker->mesh());
            // An edge that left [e, 2e] this step is frozen until the next: a few percent of slack.
            expectWellShaped(tracker->mesh(), frame.field, tracker->edgeLength(), 0.05);
        },
        {},
        [&](const FieldImage& field) {
            const TrackingStep s = tracker->step(field);
            run.reseeds += s.reseeded;
            run.surgeries += s.surgery.kind != SurgeryKind::None;
            const TrackedMesh& mesh = tracker->mesh();
            run.mismatches += !resolvableTopology(field, tracker->edgeLength())
                                   .sameAs(surfaceTopology(mesh.triangles, mesh.positions.size()));
            run.worstPhi = std::max(run.worstPhi, worstPhiVoxels(mesh, field, s.quasiCritical));
            ++run.steps;
        });
    return run;
}

// A box opening into a torus (four holes open at once, then join into one): both events are cut
// and closed where they happen (stage 2), the tracked mesh's topology is the marching-cubes
// mesh's after every step, and every frame is a closed 2-manifold on the surface.
TEST(MeshTracker, FollowsABoxOpeningHolesIntoATorus)
{
    const double h = 0.5;
    const TopologyMorph run = trackTopologyMorph(makeBox(8.0, h), makeTorus(8.0, 3.0, h));
    EXPECT_GT(run.steps, 10u);
    EXPECT_EQ(run.reseeds, 0u);    // both events cut and closed (stage 2) ...
    EXPECT_EQ(run.surgeries, 2u);  // ... the four holes opening (bridges), then joining into one (caps)
    EXPECT_EQ(run.mismatches, 0u);
    EXPECT_LT(run.worstPhi, 0.05);
    ASSERT_EQ(run.frames.size(), 3u);
    EXPECT_EQ(test::meshTopology(run.frames.back().triangleMesh()).eulerCharacteristic(), 0);  // a torus
}

// A ball opening into a torus: its poles sink until they meet in the middle and the surface opens
// a tunnel. Whichever stage takes the event (today the mesh is seeded again, stage 1), the
// topology is the marching-cubes mesh's after every step and every frame a closed 2-manifold on
// the surface.
TEST(MeshTracker, FollowsABallOpeningIntoATorus)
{
    const double h = 0.5;
    const TopologyMorph run = trackTopologyMorph(makeSphere(8.0, h), makeTorus(8.0, 3.0, h));
    EXPECT_GT(run.steps, 10u);
    EXPECT_EQ(run.mismatches, 0u);
    EXPECT_LT(run.worstPhi, 0.05);
    ASSERT_EQ(run.frames.size(), 3u);
    EXPECT_EQ(test::meshTopology(run.frames.back().triangleMesh()).eulerCharacteristic(), 0);  // a torus
}

/// Two balls of radius r centred at (+-centre, 0, 0): one shell apart, one joined.
FieldImage twoBalls(double r, double centre, double h)
{
    AnalyticSdf sdf;
    const Vec3d c(centre, 0.0, 0.0);
    sdf.distance = [=](const Vec3d& p) { return std::min((p - c).length(), (p + c).length()) - r; };
    sdf.bounds = openvdb::BBoxd(Vec3d(-centre - r, -r, -r), Vec3d(centre + r, r, r));
    sdf.surfaceArea = 8.0 * M_PI * r * r;
    sdf.description = "two balls";
    return rasterizeSdf(sdf, h);
}

/// The steps between two frames of the sequences below (frames, not steps, are what people see).
constexpr int kStepsPerFrame = 4;

/// What tracking through a topology event went through.
struct EventRun {
    std::size_t steps = 0, mismatches = 0, reseeds = 0;
    std::size_t invertedAfter = 0;  // triangles facing against grad phi two frames after the event
    std::vector<Surgery> surgeries;
    double keptFar = 1.0;        // share of the ids farther than 3e from the event that survived it
    double worstPhiAfter = 0.0;  // voxels, the two frames after the event
    bool manifoldAfter = false;  // two frames after the event
};

/// Steps a tracker through `fields(k)`, k = 1 .. steps, the vertices moved by `move` first.
EventRun trackEvent(const std::function<FieldImage(int)>& fields, const std::function<Vec3d(const Vec3d&)>& move,
                    int steps)
{
    MeshTracker tracker(fields(0));
    EventRun run;
    int event = -1;
    for (int k = 1; k <= steps; ++k) {
        const FieldImage field = fields(k);
        const TrackedMesh before = tracker.mesh();
        const TrackingStep s = tracker.step(field, move);
        const TrackedMesh& mesh = tracker.mesh();
        run.mismatches += !resolvableTopology(field, tracker.edgeLength())
                               .sameAs(surfaceTopology(mesh.triangles, mesh.positions.size()));
        run.reseeds += s.reseeded;
        ++run.steps;
        if (s.reseeded) event = k;
        if (s.surgery.kind != SurgeryKind::None) {
            run.surgeries.push_back(s.surgery);
            event = k;
            const std::set<std::uint32_t> kept(mesh.ids.begin(), mesh.ids.end());
            std::size_t far = 0, survived = 0;
            for (std::size_t v = 0; v < before.ids.size(); ++v)
                if ((before.positions[v] - s.surgery.centre).length() > 3.0 * tracker.edgeLength()) {
                    ++far;
                    survived += kept.count(before.ids[v]);
                }
            run.keptFar = std::min(run.keptFar, double(survived) / double(far));
        } else if (event > 0 && k <= event + 2 * kStepsPerFrame) {
            run.worstPhiAfter = std::max(run.worstPhiAfter, worstPhiVoxels(mesh, field, s.quasiCritical));
            if (k == event + 2 * kStepsPerFrame)
                run.manifoldAfter = test::meshTopology(mesh.triangleMesh()).closedManifold();
        } else if (event > 0 && k == event + 2 * kStepsPerFrame + 1) {
            run.invertedAfter = s.inverted;  // as the step began: as two frames after the event left it
        }
    }
    return run;
}

/// The topology right after every step, and two frames after the event a closed 2-manifold on
/// the surface with no triangle folded.
void expectFollowed(const EventRun& run)
{
    EXPECT_EQ(run.mismatches, 0u) << "steps whose tracked topology was not the marching-cubes mesh's";
    EXPECT_TRUE(run.manifoldAfter);
    EXPECT_EQ(run.invertedAfter, 0u);
    EXPECT_LT(run.worstPhiAfter, 0.05);
}

/// ... and the event handled by stage 2 as `kind`, the ids away from it kept.
void expectSurgery(const EventRun& run, SurgeryKind kind)
{
    expectFollowed(run);
    EXPECT_EQ(run.reseeds, 0u);
    ASSERT_EQ(run.surgeries.size(), 1u);
    EXPECT_EQ(run.surgeries[0].kind, kind);
    EXPECT_GE(run.keptFar, 0.9);
}

// Two balls moving together a tenth of a voxel a step until they join: stage 2 bridges the two
// meshes where they touch.
TEST(MeshTracker, FollowsTwoBallsMergingByBridgingTheirMeshesWhereTheyTouch)
{
    const double r = 6.0, h = 0.5, speed = 0.025;  // each ball, per step
    const EventRun run = trackEvent([&](int k) { return twoBalls(r, r + 0.6 - speed * k, h); },
                                    [&](const Vec3d& p) { return Vec3d(p.x() > 0.0 ? -speed : speed, 0.0, 0.0); }, 40);
    expectSurgery(run, SurgeryKind::Bridge);
}

// The same balls moving apart: the neck pinches off and stage 2 caps both sides.
TEST(MeshTracker, FollowsTwoBallsPartingByCappingBothSidesOfTheNeck)
{
    const double r = 6.0, h = 0.5, speed = 0.025;
    const EventRun run = trackEvent([&](int k) { return twoBalls(r, r - 0.6 + speed * k, h); },
                                    [&](const Vec3d& p) { return Vec3d(p.x() > 0.0 ? speed : -speed, 0.0, 0.0); }, 40);
    expectSurgery(run, SurgeryKind::Cap);
}

/// A big ball of radius 6 at (-8, 0, 0) and a small one of radius `small` at (6, 0, 0) (none
/// when negative).
FieldImage bigAndSmallBall(double small, double h)
{
    AnalyticSdf sdf;
    const Vec3d big(-8.0, 0.0, 0.0), little(6.0, 0.0, 0.0);
    sdf.distance = [=](const Vec3d& p) { return std::min((p - big).length() - 6.0, (p - little).length() - small); };
    sdf.bounds = openvdb::BBoxd(Vec3d(-14.0, -6.0, -6.0), Vec3d(6.0 + small, 6.0, 6.0));
    sdf.surfaceArea = 4.0 * M_PI * (36.0 + small * small);
    sdf.description = "a big and a small ball";
    return rasterizeSdf(sdf, h);
}

TEST(TrackedMesh, DropsTheShellsUnderAnExtentKeepingTheOthersAndTheirIds)
{
    const double h = 0.5;
    TrackedMesh mesh = TrackedMesh::of(meshLevelSet(bigAndSmallBall(0.6, h)));
    ASSERT_EQ(surfaceTopology(mesh.triangles, mesh.positions.size()).shells, 2u);
    const TrackedMesh before = mesh;
    EXPECT_EQ(mesh.dropShellsUnder(3.0 * h), 1u);
    const SurfaceTopology merged = surfaceTopology(mesh.triangles, mesh.positions.size());
    EXPECT_EQ(merged.euler, 2);
    EXPECT_EQ(merged.shells, 1u);
    std::size_t bigBefore = 0;
    for (const Vec3d& p : before.positions) bigBefore += p.x() < 0.0;
    EXPECT_EQ(mesh.positions.size(), bigBefore);
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        EXPECT_NEAR((mesh.positions[v] - Vec3d(-8.0, 0.0, 0.0)).length(), 6.0, h);
        const auto was = std::find(before.ids.begin(), before.ids.end(), mesh.ids[v]);
        ASSERT_NE(was, before.ids.end());
        EXPECT_EQ(before.positions[std::size_t(was - before.ids.begin())], mesh.positions[v]);
    }
    EXPECT_EQ(mesh.dropShellsUnder(3.0 * h), 0u);
}

// A small ball shrinking away beside a big one, a tenth of a voxel a step: its tracked shell
// is dropped once it is under the mesh's resolution (2e across), the marching-cubes speck it
// leaves is not counted, and the big ball goes on with every vertex id: no seed again.
TEST(MeshTracker, DropsASmallBallShrinkingAwayAndKeepsTheBigOnesIds)
{
    const double h = 0.5;
    MeshTracker tracker(bigAndSmallBall(2.0, h));
    const TrackedMesh first = tracker.mesh();
    std::vector<std::uint32_t> bigIds;
    for (std::size_t v = 0; v < first.positions.size(); ++v)
        if (first.positions[v].x() < 0.0) bigIds.push_back(first.ids[v]);
    std::size_t vanished = 0, reseeds = 0, surgeries = 0;
    for (int k = 1; k <= 36; ++k) {
        const FieldImage field = bigAndSmallBall(2.0 - 0.05 * k, h);
        const TrackingStep s = tracker.step(field);
        vanished += s.vanishedShells;
        reseeds += s.reseeded;
        surgeries += s.surgery.kind != SurgeryKind::None;
        const TrackedMesh& mesh = tracker.mesh();
        EXPECT_EQ(surfaceTopology(mesh.triangles, mesh.positions.size()).shells, vanished > 0 ? 1u : 2u);
        EXPECT_TRUE(test::meshTopology(mesh.triangleMesh()).closedManifold()) << "step " << k;
    }
    EXPECT_EQ(vanished, 1u);
    EXPECT_EQ(reseeds, 0u);
    EXPECT_EQ(surgeries, 0u);
    const TrackedMesh& last = tracker.mesh();
    std::vector<std::uint32_t> lastIds = last.ids;
    std::sort(lastIds.begin(), lastIds.end());
    std::sort(bigIds.begin(), bigIds.end());
    EXPECT_EQ(lastIds, bigIds);
    expectWellShaped(last, bigAndSmallBall(-1.0, h), tracker.edgeLength());  // the big ball alone
}

/// A regular tetrahedron of edge `edge` with its first corner at `at`, facing outwards; ids from `firstId`.
TrackedMesh tetrahedron(const Vec3d& at, double edge, std::uint32_t firstId)
{
    TriangleMesh mesh;
    const double s = edge / std::sqrt(8.0);
    for (const Vec3d& c : {Vec3d(1, 1, 1), Vec3d(1, -1, -1), Vec3d(-1, 1, -1), Vec3d(-1, -1, 1)}) {
        const Vec3d p = at + (c - Vec3d(1, 1, 1)) * s;
        mesh.positions.push_back({float(p.x()), float(p.y()), float(p.z())});
    }
    mesh.triangles = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
    return TrackedMesh::of(mesh, firstId);
}

// A tetrahedron with edges under e passes the link condition on every edge (its two ends share
// exactly the two opposite vertices), but collapsing one leaves two triangles back to back: a
// shell that is no surface. Beside another shell (a lone one of four vertices is never
// collapsed), it must stay as it is.
TEST(EdgeRemesher, NeverCollapsesATetrahedronIntoTwoTrianglesBackToBack)
{
    TrackedMesh mesh = tetrahedron(Vec3d(0.0), 0.5, 0);
    const TrackedMesh other = tetrahedron(Vec3d(10.0, 0.0, 0.0), 1.5, 4);
    for (std::uint32_t v = 0; v < 4; ++v)
        mesh.positions.push_back(other.positions[v]), mesh.ids.push_back(other.ids[v]);
    for (const auto& t : other.triangles) mesh.triangles.push_back({t[0] + 4, t[1] + 4, t[2] + 4});
    mesh.nextId = 8;
    const TrackedMesh before = mesh;
    EdgeMemory memory;
    const RemeshCounts counts = alterMesh(mesh, memory, {}, {1.0});
    EXPECT_EQ(counts.collapses, 0u);
    EXPECT_EQ(mesh.ids, before.ids);
    EXPECT_EQ(mesh.triangles, before.triangles);
    EXPECT_TRUE(test::meshTopology(mesh.triangleMesh()).closedManifold());
}

/// A pseudo-random move of up to `amplitude` along each axis, a function of the point alone.
Vec3d scramble(const Vec3d& p, double amplitude)
{
    const auto noise = [&](double a, double b, double c) {
        const double x = std::sin(p.x() * a + p.y() * b + p.z() * c) * 43758.5453;
        return 2.0 * (x - std::floor(x)) - 1.0;
    };
    return amplitude * Vec3d(noise(12.99, 78.23, 37.72), noise(39.35, 11.13, 83.15), noise(73.16, 52.24, 9.46));
}

// Folds over more than 1% of the triangles feed themselves (unfolding and remeshing among them
// fold more): such a mesh has lost the surface and is seeded again, well shaped. A light jitter
// is followed in place.
TEST(MeshTracker, SeedsAgainAMeshFoldedOverMoreThanOnePercentOfItsTriangles)
{
    const FieldImage field = makeSphere(8.0, 0.5);
    for (const double amplitude : {0.1, 1.5}) {
        MeshTracker tracker(field);
        const double e = tracker.edgeLength();
        const std::size_t triangles = tracker.mesh().triangles.size();
        const TrackingStep s = tracker.step(field, [&](const Vec3d& p) { return scramble(p, amplitude * e); });
        const bool lost = double(s.inverted) > MeshTracker::kLostFoldedShare * double(triangles);
        EXPECT_EQ(lost, amplitude > 1.0) << s.inverted << " of " << triangles << " triangles folded";
        EXPECT_EQ(s.folded, lost);
        EXPECT_EQ(s.reseeded, lost);
        for (int k = 0; k < 4; ++k) EXPECT_EQ(tracker.step(field).inverted, 0u) << "amplitude " << amplitude;
        expectWellShaped(tracker.mesh(), field, e);
    }
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
