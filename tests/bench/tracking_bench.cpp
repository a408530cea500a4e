// SPDX-License-Identifier: Apache-2.0
// The tracked mesh's cost per evolution step beside re-meshing the whole model, in one run.
// Run: build/tests/bench/tracking_bench
//
// BM_TrackingClayBall : the clay ball (radius 50, voxel 0.5, `sculpt new`'s default) following a
//                       box of the same area for 24 evolution steps (a frame before and after).
// BM_TrackingMorph/P  : CGAL's meshes (libcgal-demo), P = 0 elephant -> camel: the whole
//                       `sculpt morph --frames 3 --align --tracked` motion at the target's longest
//                       side / 256 (both passes: every step is tracked).
// Per step, medians in ms: track_ms, the tracker's step (projection, remeshing, relaxation and the
// topology check); check_ms, that check alone (the welded marching-cubes mesh, which the tracker
// builds inside its step); rebuild_ms, IncrementalMesher::rebuild of the same field (the reference:
// re-meshing the whole model). Also the seeding (seed_s), vertices at the start and the end, the
// worst smallest angle over the sequence, flagged points, steps that seeded the mesh again
// (reseeds) and the segments a TrackedSequence of the frames makes of it (segments).

#include "core/io/mesh_import.h"
#include "core/mesh/incremental_mesher.h"
#include "core/motion/level_set_evolution.h"
#include "core/motion/morph.h"
#include "core/primitives/analytic_shapes.h"
#include "core/tracking/mesh_tracker.h"
#include "core/tracking/tracked_mesh_quality.h"
#include "core/tracking/tracked_sequence.h"
#include "tests/support/cgal_data.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

namespace {

using namespace sculpt;
using Clock = std::chrono::steady_clock;

template <typename Work>
double millisecondsOf(Work work)
{
    const auto start = Clock::now();
    work();
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double median(std::vector<double> values)
{
    if (values.empty()) return 0.0;
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(values.size() / 2), values.end());
    return values[values.size() / 2];
}

/// Each step's costs and what the tracked mesh went through.
class StepLog {
public:
    void seed(const FieldImage& field)
    {
        mSeedSeconds = millisecondsOf([&] { mTracker.emplace(field); }) / 1000.0;
        mFirstVertices = mTracker->mesh().positions.size();
    }

    void step(const FieldImage& field)
    {
        TrackingStep report;
        mTrack.push_back(millisecondsOf([&] { report = mTracker->step(field); }));
        mCheck.push_back(millisecondsOf([&] { benchmark::DoNotOptimize(meshLevelSet(field)); }));
        IncrementalMesher mesher;
        mRebuild.push_back(millisecondsOf([&] { mesher.rebuild(field); }));
        mFlagged += report.quasiCritical.size();
        mReseeds += report.reseeded;
        mEdits.insert(mEdits.end(), report.edits.begin(), report.edits.end());
        const TrackedMesh& mesh = mTracker->mesh();
        for (const auto& t : mesh.triangles)
            mWorstAngle = std::min(
                mWorstAngle, smallestAngleDegrees(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]));
    }

    bool seeded() const { return mTracker.has_value(); }

    void frame()
    {
        mSequence.add(mTracker->mesh(), mEdits);
        mEdits.clear();
    }

    void report(benchmark::State& state) const
    {
        state.counters["track_ms"] = median(mTrack);
        state.counters["check_ms"] = median(mCheck);
        state.counters["rebuild_ms"] = median(mRebuild);
        state.counters["track_per_rebuild"] = median(mTrack) / median(mRebuild);
        state.counters["seed_s"] = mSeedSeconds;
        state.counters["steps"] = double(mTrack.size());
        state.counters["vertices_first"] = double(mFirstVertices);
        state.counters["vertices_last"] = double(mTracker->mesh().positions.size());
        state.counters["worst_angle_deg"] = mWorstAngle;
        state.counters["flagged"] = double(mFlagged);
        state.counters["reseeds"] = double(mReseeds);
        state.counters["segments"] = double(mSequence.segments().size());
    }

private:
    std::optional<MeshTracker> mTracker;
    std::vector<double> mTrack, mCheck, mRebuild;
    double mSeedSeconds = 0.0, mWorstAngle = 180.0;
    std::size_t mFirstVertices = 0, mFlagged = 0, mReseeds = 0;
    std::vector<MeshEdit> mEdits;  // since the last frame
    TrackedSequence mSequence;
};

void BM_TrackingClayBall(benchmark::State& state)
{
    const double radius = 50.0, h = 0.5;
    const FieldImage box = makeBox(radius * std::sqrt(M_PI / 6.0), h);
    for (auto _ : state) {
        FieldImage field = makeSphere(radius, h);
        StepLog log;
        log.seed(field);
        log.frame();
        MotionTerms terms;
        terms.target = TargetTerm{box.gridPtr(), 1.0, 0.0};
        LevelSetEvolution evolution(field, terms);
        for (int k = 0; k < 24; ++k) {
            evolution.step();
            log.step(field);
        }
        log.frame();
        log.report(state);
    }
}

void BM_TrackingMorph(benchmark::State& state)
{
    static const char* names[][2] = {{"elephant.off", "camel.off"}};
    const auto sourcePath = test::cgalMesh(names[state.range(0)][0]);
    const auto targetPath = test::cgalMesh(names[state.range(0)][1]);
    if (sourcePath.empty() || targetPath.empty()) return state.SkipWithError("install libcgal-demo");
    const TriangleMesh targetMesh = readMesh(targetPath);
    const double voxel = voxelSizeFor(targetMesh);
    const FieldImage source = meshToField(readMesh(sourcePath), voxel), target = meshToField(targetMesh, voxel);
    MorphOptions options;
    options.frames = 3;
    options.align = true;
    for (auto _ : state) {
        StepLog log;
        morph(
            source, target, options,
            [&](const MorphFrame& frame) {
                if (!log.seeded()) log.seed(frame.field);
                log.frame();
            },
            {}, [&](const FieldImage& field) { log.step(field); });
        log.report(state);
    }
}

BENCHMARK(BM_TrackingClayBall)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);
BENCHMARK(BM_TrackingMorph)->Arg(0)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

}  // namespace
