// SPDX-License-Identifier: Apache-2.0
// A tracked sequence keeps one segment while the tracker only splits and collapses edges: each
// frame of it is exactly the tracked surface of that frame (the tracker's vertices where they
// are, the others on its surface: at an edge's midpoint before a split, on their keeper after a
// collapse), closed and 2-manifold; a new segment starts where merged vertices would pass a
// tenth of the segment's, or where the edits do not replay (a mesh seeded again).

#include "core/primitives/analytic_shapes.h"
#include "core/primitives/sdf_rasterizer.h"
#include "core/tracking/mesh_tracker.h"
#include "core/tracking/tracked_sequence.h"
#include "tests/support/mesh_checks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <unordered_set>

namespace sculpt {
namespace {

constexpr double kVoxel = 0.5;

/// A capsule around the x axis: the points within `radius` of the segment from -half to half.
FieldImage capsule(double half, double radius)
{
    AnalyticSdf sdf;
    sdf.distance = [=](const openvdb::Vec3d& p) {
        return (p - openvdb::Vec3d(std::clamp(p.x(), -half, half), 0.0, 0.0)).length() - radius;
    };
    sdf.bounds =
        openvdb::BBoxd(openvdb::Vec3d(-half - radius, -radius, -radius), openvdb::Vec3d(half + radius, radius, radius));
    sdf.surfaceArea = 4.0 * M_PI * radius * (radius + half);
    sdf.description = "capsule";
    return rasterizeSdf(sdf, kVoxel);
}

/// Frames of a tracked mesh, kept as the tracker had them and in two sequences: with the edits
/// and without.
struct TrackedRun {
    std::vector<TrackedMesh> frames;
    TrackedSequence sequence, plain;
    std::size_t splits = 0, collapses = 0, reseeds = 0;
};

/// A capsule going through `shapes` ({half length, radius}), a quarter voxel a step at most,
/// tracked; a frame every four steps.
TrackedRun trackCapsule(const std::vector<std::array<double, 2>>& shapes)
{
    TrackedRun run;
    MeshTracker tracker(capsule(shapes[0][0], shapes[0][1]));
    std::vector<MeshEdit> edits;
    const auto frame = [&] {
        run.frames.push_back(tracker.mesh());
        run.sequence.add(tracker.mesh(), edits);
        run.plain.add(tracker.mesh());
        edits.clear();
    };
    frame();
    int steps = 0;
    for (std::size_t k = 1; k < shapes.size(); ++k) {
        const std::array<double, 2> from = shapes[k - 1], to = shapes[k];
        const double farthest = std::max(std::abs(to[0] - from[0]), std::abs(to[1] - from[1]));
        const int n = int(std::ceil(farthest / (0.25 * kVoxel)));
        for (int i = 1; i <= n; ++i) {
            const double t = double(i) / n;
            const TrackingStep s =
                tracker.step(capsule(from[0] + t * (to[0] - from[0]), from[1] + t * (to[1] - from[1])));
            edits.insert(edits.end(), s.edits.begin(), s.edits.end());
            run.splits += s.splits;
            run.collapses += s.collapses;
            run.reseeds += s.reseeded;
            if (++steps % 4 == 0) frame();
        }
    }
    if (steps % 4 != 0) frame();
    return run;
}

/// Frame `j` of `segment` is the surface of `truth`: the same positions for the same ids, the
/// same area and volume, closed and 2-manifold of the same Euler characteristic.
void expectTheTrackedSurface(const TrackedSegment& segment, std::size_t j, const TrackedMesh& truth)
{
    std::unordered_map<std::uint32_t, std::size_t> index;
    for (std::size_t v = 0; v < truth.ids.size(); ++v) index[truth.ids[v]] = v;
    std::size_t found = 0;
    for (std::size_t v = 0; v < segment.ids.size(); ++v) {
        const auto it = index.find(segment.ids[v]);
        if (it == index.end()) continue;
        ++found;
        const openvdb::Vec3d& p = truth.positions[it->second];
        ASSERT_EQ(segment.positions[j][v], (std::array<float, 3>{float(p.x()), float(p.y()), float(p.z())}));
    }
    EXPECT_EQ(found, truth.ids.size());
    const TriangleMesh mine = segment.frameMesh(j), theirs = truth.triangleMesh();
    const test::MeshTopology topology = test::meshTopology(mine);
    EXPECT_TRUE(topology.closedManifold());
    EXPECT_EQ(topology.eulerCharacteristic(), test::meshTopology(theirs).eulerCharacteristic());
    EXPECT_NEAR(test::meshArea(mine), test::meshArea(theirs), 1e-5 * test::meshArea(theirs));
    EXPECT_NEAR(test::meshVolume(mine), test::meshVolume(theirs), 1e-5 * test::meshVolume(theirs));
}

void expectEveryFrameTheTrackedSurface(const TrackedRun& run)
{
    ASSERT_EQ(run.sequence.frameCount(), int(run.frames.size()));
    for (const TrackedSegment& segment : run.sequence.segments())
        for (std::size_t j = 0; j < segment.positions.size(); ++j) {
            SCOPED_TRACE("frame " + std::to_string(segment.firstFrame + int(j)));
            expectTheTrackedSurface(segment, j, run.frames[std::size_t(segment.firstFrame) + j]);
        }
}

// A ball drawn out into a capsule, then thinned: edges split at the ends and collapse around the
// middle; without the edits every frame after a change starts a segment, with them the run is one.
TEST(TrackedSequence, KeepsOneSegmentThroughSplitsAndCollapsesEachFrameTheTrackedSurface)
{
    const TrackedRun run = trackCapsule({{0.0, 9.0}, {10.0, 6.0}, {10.0, 5.0}});
    EXPECT_EQ(run.reseeds, 0u);
    EXPECT_GT(run.splits, 0u);
    EXPECT_GT(run.collapses, 0u);
    EXPECT_GT(run.plain.segments().size(), 2u);
    ASSERT_EQ(run.sequence.segments().size(), 1u);
    EXPECT_GT(run.sequence.segments()[0].ids.size(), run.frames.front().ids.size());
    expectEveryFrameTheTrackedSurface(run);
}

// A capsule shortened into a ball, two fifths of its area gone: merged vertices would pile up, so
// a segment ends before they pass a tenth of its vertices and the next starts from the tracked
// mesh as it is; still fewer segments than frames with collapses.
TEST(TrackedSequence, StartsASegmentBeforeMergedVerticesPassATenth)
{
    const TrackedRun run = trackCapsule({{10.0, 6.0}, {0.0, 6.0}});
    EXPECT_EQ(run.reseeds, 0u);
    ASSERT_GT(run.collapses, 0u);
    EXPECT_GT(run.sequence.segments().size(), 1u);
    EXPECT_LT(run.sequence.segments().size(), run.plain.segments().size());
    for (const TrackedSegment& segment : run.sequence.segments()) {
        const TrackedMesh& last = run.frames[std::size_t(segment.firstFrame) + segment.positions.size() - 1];
        const std::unordered_set<std::uint32_t> kept(last.ids.begin(), last.ids.end());
        std::size_t merged = 0;
        for (const std::uint32_t id : segment.ids) merged += kept.count(id) == 0;
        EXPECT_LE(double(merged), TrackedSequence::kMostMerged * double(segment.ids.size()));
    }
    expectEveryFrameTheTrackedSurface(run);
}

using Triangle = std::array<std::uint32_t, 3>;

std::uint32_t indexOf(const TrackedMesh& mesh, std::uint32_t id)
{
    return std::uint32_t(std::find(mesh.ids.begin(), mesh.ids.end(), id) - mesh.ids.begin());
}

/// A triangle of `mesh` holding edge from -> to (indices), and its third vertex.
std::pair<std::size_t, std::uint32_t> triangleOf(const TrackedMesh& mesh, std::uint32_t from, std::uint32_t to)
{
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            if (mesh.triangles[t][k] == from && mesh.triangles[t][(k + 1) % 3] == to)
                return {t, mesh.triangles[t][(k + 2) % 3]};
    ADD_FAILURE() << "no edge " << from << " -> " << to;
    return {0, from};
}

/// The remesher's collapse of `goneId` into `keptId` at their midpoint (edge_remesher.cpp), by hand.
MeshEdit collapse(TrackedMesh& mesh, std::uint32_t keptId, std::uint32_t goneId)
{
    const std::uint32_t keep = indexOf(mesh, keptId), gone = indexOf(mesh, goneId);
    mesh.positions[keep] = 0.5 * (mesh.positions[keep] + mesh.positions[gone]);
    std::vector<Triangle> kept;
    for (Triangle t : mesh.triangles) {
        if (std::count(t.begin(), t.end(), keep) && std::count(t.begin(), t.end(), gone)) continue;
        std::replace(t.begin(), t.end(), gone, keep);
        kept.push_back(t);
    }
    mesh.triangles = kept;
    mesh.dropUnusedVertices();
    return {MeshEdit::Kind::Collapse, keptId, goneId, 0};
}

/// The remesher's split of edge a -> b at its midpoint, by hand.
MeshEdit split(TrackedMesh& mesh, std::uint32_t aId, std::uint32_t bId)
{
    const std::uint32_t a = indexOf(mesh, aId), b = indexOf(mesh, bId), m = std::uint32_t(mesh.ids.size());
    const auto [t1, c] = triangleOf(mesh, a, b);
    const auto [t2, d] = triangleOf(mesh, b, a);
    mesh.positions.push_back(0.5 * (mesh.positions[a] + mesh.positions[b]));
    mesh.ids.push_back(mesh.nextId++);
    mesh.triangles[t1] = {a, m, c};
    mesh.triangles[t2] = {b, m, d};
    mesh.triangles.push_back({m, b, c});
    mesh.triangles.push_back({m, a, d});
    return {MeshEdit::Kind::Split, aId, bId, mesh.ids.back()};
}

// A collapse merges the edges (k, c) and (g, c) of the triangle (k, g, c) into one; a split of
// that edge, either way round, splits both, and the flat triangle between them, by the new
// vertex and one riding on it (an id only the segment has); where the edge's other side
// collapsed too (a chain of two flat triangles, around c and around g), by three. One segment,
// each frame the tracked surface.
TEST(TrackedSequence, KeepsTheSegmentWhenASplitFollowsCollapsesOnTheEdgesItMerged)
{
    TrackedRun run;
    TrackedMesh mesh = MeshTracker(makeSphere(8.0, kVoxel)).mesh();
    run.frames.push_back(mesh);
    run.sequence.add(mesh);
    for (std::size_t variant = 0; variant < 3; ++variant) {
        const Triangle t = mesh.triangles[variant * mesh.triangles.size() / 3];
        const std::uint32_t k = mesh.ids[t[0]], g = mesh.ids[t[1]], c = mesh.ids[t[2]];
        std::vector<MeshEdit> edits{collapse(mesh, k, g)};
        if (variant == 2) {  // the third vertex of the triangle holding c -> k merges into c
            const std::uint32_t z = mesh.ids[triangleOf(mesh, indexOf(mesh, c), indexOf(mesh, k)).second];
            edits.push_back(collapse(mesh, c, z));
        }
        edits.push_back(variant == 1 ? split(mesh, c, k) : split(mesh, k, c));
        run.frames.push_back(mesh);
        run.sequence.add(mesh, edits);
    }
    ASSERT_EQ(run.sequence.segments().size(), 1u);
    const std::vector<std::uint32_t>& ids = run.sequence.segments()[0].ids;
    EXPECT_EQ(std::count_if(ids.begin(), ids.end(), [&](std::uint32_t id) { return id >= mesh.nextId; }), 4);
    expectEveryFrameTheTrackedSurface(run);
}

// Edits that are not this mesh's (another seed's ids) do not replay: a new segment, as the
// frame of a mesh seeded again starts one.
TEST(TrackedSequence, StartsASegmentWhereTheEditsDoNotReplay)
{
    const TrackedMesh ball = MeshTracker(makeSphere(8.0, kVoxel)).mesh();
    TrackedSequence sequence;
    sequence.add(ball);
    sequence.add(ball);
    EXPECT_EQ(sequence.segments().size(), 1u);
    sequence.add(ball, {{MeshEdit::Kind::Collapse, ball.nextId, ball.nextId + 1, 0}});
    EXPECT_EQ(sequence.segments().size(), 2u);
    TrackedMesh reseeded = ball;
    for (std::uint32_t& id : reseeded.ids) id += ball.nextId;
    sequence.add(reseeded);
    ASSERT_EQ(sequence.segments().size(), 3u);
    EXPECT_EQ(sequence.segments().back().ids, reseeded.ids);
    EXPECT_EQ(sequence.frameCount(), 4);
}

}  // namespace
}  // namespace sculpt
