// SPDX-License-Identifier: Apache-2.0
#include "core/tracking/mesh_tracker.h"

#include "core/mesh/incremental_mesher.h"
#include "core/tracking/edge_hold.h"
#include "core/tracking/mesh_adjacency.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>

namespace sculpt {

namespace {

using openvdb::Vec3d;

Vec3d normalOf(const TrackedMesh& mesh, const std::array<std::uint32_t, 3>& t)
{
    const Vec3d& a = mesh.positions[t[0]];
    return (mesh.positions[t[1]] - a).cross(mesh.positions[t[2]] - a);
}

}  // namespace

MeshTracker::MeshTracker(const FieldImage& field, const TrackerOptions& options)
    : mOptions(options), mEdge(options.edgeVoxels * field.voxelSize())
{
    seed(field, resolvableSurface(field));
}

TrackedMesh MeshTracker::resolvableSurface(const FieldImage& field) const
{
    TrackedMesh surface = TrackedMesh::of(meshLevelSet(field));
    surface.dropShellsUnder(kResolvableEdges * mEdge);
    return surface;
}

void MeshTracker::seed(const FieldImage& field, const TrackedMesh& surface)
{
    const std::uint32_t firstId = mMesh.nextId;
    mMesh = surface;
    for (std::uint32_t& id : mMesh.ids) id += firstId;
    mMesh.nextId += firstId;
    mMemory = {};
    for (int i = 0; i < mOptions.seedSteps; ++i)
        advance(field, {}, {mEdge, mOptions.seedShortestEdges * mEdge, mOptions.seedLongestEdges * mEdge, true},
                relaxation(mOptions.gain, mOptions.conjugateGradientSteps), false);
}

TrackingStep MeshTracker::step(const FieldImage& field, const std::function<Vec3d(const Vec3d&)>& displacement)
{
    TrackingStep report =
        advance(field, displacement, {mEdge}, relaxation(mOptions.gain, mOptions.conjugateGradientSteps), true);
    const TrackedMesh mc = resolvableSurface(field);
    report.folded = double(report.inverted) > kLostFoldedShare * double(mMesh.triangles.size());
    if (report.folded) return reseed(field, mc, report);
    const SurfaceTopology truth = surfaceTopology(mc.triangles, mc.positions.size());
    if (truth.sameAs(surfaceTopology(mMesh.triangles, mMesh.positions.size()))) return report;
    // A part that shrank under the resolution has left the ground truth: it leaves the mesh too.
    report.vanishedShells = mMesh.dropShellsUnder(kResolvableEdges * mEdge);
    if (report.vanishedShells > 0) {
        project(field);  // the per-vertex normals and flags, renumbered
        report.quasiCritical = flagged();
        if (truth.sameAs(surfaceTopology(mMesh.triangles, mMesh.positions.size()))) return report;
    }
    report.surgery = operateOnTopology(mMesh, mNormals, mQuasiCritical, field, truth);
    if (report.surgery.kind != SurgeryKind::None) {
        // The cut's new vertices and long edges: onto the surface and into [e, 2e]. Its fans are
        // far from the rest shape, where the co-rotational linearisation overshoots and folds
        // them: they relax a gentler fraction of the way, their edges left to the remesher.
        const RelaxOptions settling = relaxation(mOptions.settleGain, mOptions.settleConjugateGradientSteps);
        for (int i = 0; i < kSettleSteps; ++i) {
            const TrackingStep settle = advance(field, {}, {mEdge}, settling, false);
            report.splits += settle.splits;
            report.collapses += settle.collapses;
            report.edits.insert(report.edits.end(), settle.edits.begin(), settle.edits.end());
            report.quasiCritical = settle.quasiCritical;
        }
        const std::vector<std::uint8_t> inverted = invertedTriangles();
        if (std::find(inverted.begin(), inverted.end(), 1) == inverted.end()) return report;
        report.surgery = {};  // it left the mesh folded: stage 1 after all
    }
    return reseed(field, mc, report);
}

TrackingStep MeshTracker::reseed(const FieldImage& field, const TrackedMesh& surface, TrackingStep report)
{
    seed(field, surface);
    report.reseeded = true;
    report.quasiCritical = flagged();  // the new mesh's
    return report;
}

TrackingStep MeshTracker::advance(const FieldImage& field, const std::function<Vec3d(const Vec3d&)>& displacement,
                                  const RemeshLimits& limits, const RelaxOptions& relaxation, bool holding)
{
    if (displacement)
        for (Vec3d& p : mMesh.positions) p += displacement(p);
    project(field);
    TrackingStep report;
    const std::vector<std::uint8_t> inverted = invertedTriangles();
    for (const std::uint8_t i : inverted) report.inverted += i;
    unfold(inverted);
    // Relaxed before it is judged, a stretch spreads over the triangles around it instead of
    // splitting the one edge it reached first (a third fewer edge changes, sphere -> box).
    relax(field, relaxation);
    if (holding) holdEdges(field);
    RemeshCounts counts = alterMesh(mMesh, mMemory, inverted, limits);
    report.splits = counts.splits;
    report.collapses = counts.collapses;
    report.edits = std::move(counts.edits);
    project(field);
    relax(field, relaxation);
    if (holding) holdEdges(field);
    report.quasiCritical = flagged();
    return report;
}

RelaxOptions MeshTracker::relaxation(double gain, int conjugateGradientSteps) const
{
    return {mOptions.restEdges * mEdge, gain, conjugateGradientSteps};
}

void MeshTracker::relax(const FieldImage& field, const RelaxOptions& options)
{
    const std::vector<Vec3d> dx = relaxationStep(mMesh.positions, mMesh.triangles, mNormals, mQuasiCritical, options);
    for (std::size_t v = 0; v < dx.size(); ++v) mMesh.positions[v] += dx[v];
    project(field);
}

void MeshTracker::project(const FieldImage& field)
{
    mNormals.assign(mMesh.positions.size(), Vec3d(0.0));
    mQuasiCritical.assign(mMesh.positions.size(), 0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mMesh.positions.size(), 1024),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                          const FieldProbe probe(field.grid());
                          for (std::size_t v = range.begin(); v != range.end(); ++v) projectVertex(probe, v);
                      });
}

void MeshTracker::projectVertex(const FieldProbe& probe, std::size_t v)
{
    const Projection p = projectOntoSurface(probe, mMesh.positions[v]);
    mMesh.positions[v] = p.position;
    mQuasiCritical[v] = p.quasiCritical;
    if (p.gradient.length() > 1e-12) mNormals[v] = p.gradient.unit();
}

void MeshTracker::holdEdges(const FieldImage& field)
{
    EdgeHold hold(mMesh, mNormals, mQuasiCritical, mMemory, mEdge);
    const FieldProbe probe(field.grid());
    for (int sweep = 0; sweep < EdgeHold::kSweeps; ++sweep) {
        const std::vector<std::uint32_t> moved = hold.sweep();
        if (moved.empty()) return;
        for (const std::uint32_t v : moved) projectVertex(probe, v);
    }
}

std::vector<std::uint8_t> MeshTracker::invertedTriangles() const
{
    std::vector<std::uint8_t> inverted(mMesh.triangles.size(), 0);
    for (std::size_t t = 0; t < inverted.size(); ++t) {
        const Vec3d n = normalOf(mMesh, mMesh.triangles[t]);
        // A quasi-critical vertex's gradient gives no direction to be against.
        bool against = true;
        for (const std::uint32_t v : mMesh.triangles[t])
            against = against && !mQuasiCritical[v] && n.dot(mNormals[v]) < 0.0;
        inverted[t] = against;
    }
    return inverted;
}

void MeshTracker::unfold(const std::vector<std::uint8_t>& inverted)
{
    std::vector<std::uint8_t> moved(mMesh.positions.size(), 0);
    for (std::size_t t = 0; t < inverted.size(); ++t) {
        if (!inverted[t]) continue;
        const auto& tri = mMesh.triangles[t];
        // The vertex lowest over its opposite edge needs the smallest move to turn the triangle back.
        int lowest = 0;
        double lowestHeight = std::numeric_limits<double>::max();
        Vec3d foot(0.0);
        for (int k = 0; k < 3; ++k) {
            const Vec3d &p = mMesh.positions[tri[k]], &a = mMesh.positions[tri[(k + 1) % 3]];
            const Vec3d u = (mMesh.positions[tri[(k + 2) % 3]] - a).unitSafe(), f = a + u * (p - a).dot(u);
            if ((p - f).length() < lowestHeight) lowestHeight = (p - f).length(), lowest = k, foot = f;
        }
        const std::uint32_t v = tri[lowest];
        if (moved[v]) continue;
        moved[v] = 1;
        mMesh.positions[v] = 2.0 * foot - mMesh.positions[v];  // mirrored across the edge: the normal turns
    }
}

std::vector<QuasiCriticalPoint> MeshTracker::flagged() const
{
    std::vector<QuasiCriticalPoint> points;
    std::vector<std::uint32_t> triangleOf(mMesh.positions.size(), 0);
    for (std::uint32_t t = 0; t < mMesh.triangles.size(); ++t)
        for (const std::uint32_t v : mMesh.triangles[t]) triangleOf[v] = t;
    for (std::size_t v = 0; v < mQuasiCritical.size(); ++v)
        if (mQuasiCritical[v]) points.push_back({mMesh.ids[v], triangleOf[v], mMesh.positions[v]});
    return points;
}

}  // namespace sculpt
