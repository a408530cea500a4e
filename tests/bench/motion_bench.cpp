// SPDX-License-Identifier: Apache-2.0
// Level-set motion beside OpenVDB's own tools, in one run.
// Run: build/tests/bench/motion_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only
//
// BM_OursSmoothStep/R        : one mean-curvature step of the whole band of a radius-R sphere
//                              (TVD-RK2, band rebuilt when beta t reaches h^2/2, i.e. every 3 steps)
// BM_OpenVdbMeanCurvature/R  : tools::LevelSetFilter::meanCurvature() (one step + track every step)
// BM_OursMorph / BM_OpenVdbMorph : sphere (radius 64) -> box until every surface point is within
//                              0.4 voxel of the box (checked every 4 steps / 4 CFL steps)
// BM_OursMorphReal/P, BM_OpenVdbMorphReal/P : CGAL's meshes (libcgal-demo), P = 0 elephant ->
//                              camel, 1 bull -> homer, at the target's longest side / 256, the
//                              source aligned on the target's centroid. Ours: the whole
//                              `sculpt morph --frames 3 --align` (both passes; steps counts both). OpenVDB: tools::LevelSetMorphing from the same aligned
//                              start until converged as ours (morphConverged: within 0.4 voxel
//                              where the target is resolvable, 1.4 elsewhere), checked every 0.35
//                              time units (about 4 CFL steps), or 4000 steps. Counters: distance (resolvable) and worst
//                              distance in voxels, volume error against the target's, steps.

#include "core/io/mesh_import.h"
#include "core/mesh/field_measures.h"
#include "core/motion/level_set_evolution.h"
#include "core/motion/morph.h"
#include "core/motion/shape_distance.h"
#include "core/primitives/analytic_shapes.h"
#include "tests/support/cgal_data.h"

#include <benchmark/benchmark.h>
#include <openvdb/tools/LevelSetFilter.h>
#include <openvdb/tools/LevelSetMorph.h>

namespace {

using namespace sculpt;

void BM_OursSmoothStep(benchmark::State& state)
{
    FieldImage field = makeSphere(double(state.range(0)), 1.0);
    MotionTerms terms;
    terms.smooth = SmoothTerm{1.0, std::nullopt};
    LevelSetEvolution evolution(field, terms);
    for (auto _ : state) evolution.step();
}

void BM_OpenVdbMeanCurvature(benchmark::State& state)
{
    FieldImage field = makeSphere(double(state.range(0)), 1.0);
    openvdb::tools::LevelSetFilter<openvdb::FloatGrid> filter(field.mutableGrid());
    for (auto _ : state) filter.meanCurvature();
}

constexpr double kSphereRadius = 64.0, kBoxHalfSide = 48.0, kToleranceVoxels = 0.4;

/// Times `run(field)` morphing a fresh radius-64 sphere into the box until within tolerance;
/// `run` returns its step count.
template <typename Run>
void timeMorph(benchmark::State& state, Run run)
{
    const FieldImage box = makeBox(kBoxHalfSide, 1.0);
    int steps = 0;
    double distance = 0.0;
    for (auto _ : state) {
        state.PauseTiming();
        FieldImage field = makeSphere(kSphereRadius, 1.0);
        state.ResumeTiming();
        steps = run(field, box, distance);
    }
    state.counters["steps"] = steps;
    state.counters["distance_voxels"] = distance;
}

void BM_OursMorph(benchmark::State& state)
{
    timeMorph(state, [](FieldImage& field, const FieldImage& box, double& distance) {
        MotionTerms terms;
        terms.target = TargetTerm{box.gridPtr(), 1.0, 0.0};
        LevelSetEvolution evolution(field, terms);
        do {
            for (int i = 0; i < 4; ++i) evolution.step();
            distance = surfaceToField(field.grid(), box.grid()).maxWorld;
        } while (distance > kToleranceVoxels && evolution.stepCount() < 4000);
        return evolution.stepCount();
    });
}

void BM_OpenVdbMorph(benchmark::State& state)
{
    timeMorph(state, [](FieldImage& field, const FieldImage& box, double& distance) {
        openvdb::tools::LevelSetMorphing<openvdb::FloatGrid> morph(field.mutableGrid(), box.grid());
        int steps = 0;
        double time = 0.0;
        do {
            steps += int(morph.advect(time, time + 2.0));  // about four CFL steps at speed 1
            time += 2.0;
            distance = surfaceToField(field.grid(), box.grid()).maxWorld;
        } while (distance > kToleranceVoxels && steps < 4000);
        return steps;
    });
}

struct MeshPair {
    FieldImage source, target;
};

/// The pair `index` at the target's longest side / 256 (what `sculpt import` picks).
std::optional<MeshPair> meshPair(int64_t index)
{
    static const char* names[][2] = {{"elephant.off", "camel.off"}, {"bull.off", "homer.off"}};
    const auto sourcePath = test::cgalMesh(names[index][0]), targetPath = test::cgalMesh(names[index][1]);
    if (sourcePath.empty() || targetPath.empty()) return std::nullopt;
    const TriangleMesh targetMesh = readMesh(targetPath);
    const double voxel = voxelSizeFor(targetMesh);
    return MeshPair{meshToField(readMesh(sourcePath), voxel), meshToField(targetMesh, voxel)};
}

void countMorphResult(benchmark::State& state, const FieldImage& result, const FieldImage& target, double steps)
{
    const double h = target.voxelSize();
    const WideDistance resultDistance(result.gridPtr(), target.grid()), targetDistance(target.gridPtr(), result.grid());
    const ShapeDistance d = twoSidedDistance(result.grid(), resultDistance, target.grid(), targetDistance);
    const double targetVolume = meshVolumeArea(target).volume;
    state.counters["distance_voxels"] = d.maxResolvedWorld / h;
    state.counters["worst_voxels"] = d.maxWorld / h;
    state.counters["volume_error_pct"] = 100.0 * (meshVolumeArea(result).volume - targetVolume) / targetVolume;
    state.counters["steps"] = steps;
}

void BM_OursMorphReal(benchmark::State& state)
{
    const auto pair = meshPair(state.range(0));
    if (!pair) return state.SkipWithError("install libcgal-demo");
    MorphOptions options;
    options.frames = 3;
    options.align = true;
    std::optional<FieldImage> last;
    MorphSummary summary;
    for (auto _ : state) {
        summary = morph(pair->source, pair->target, options, [&](const MorphFrame& frame) {
            if (frame.index + 1 == options.frames) last.emplace(frame.field.grid().deepCopy());
        });
    }
    countMorphResult(state, *last, pair->target, summary.steps);
}

void BM_OpenVdbMorphReal(benchmark::State& state)
{
    const auto pair = meshPair(state.range(0));
    if (!pair) return state.SkipWithError("install libcgal-demo");
    openvdb::Vec3d shift;
    std::optional<FieldImage> field;
    int steps = 0;
    for (auto _ : state) {
        field.emplace(morphStart(pair->source, pair->target, true, shift));
        openvdb::tools::LevelSetMorphing<openvdb::FloatGrid> morph(field->mutableGrid(), pair->target.grid());
        const WideDistance targetDistance(pair->target.gridPtr(), field->grid());
        const double tolerance = kToleranceVoxels * pair->target.voxelSize();
        double time = 0.0;
        steps = 0;
        while (steps < 4000 && !morphConverged(twoSidedDistance(field->grid(), pair->target.grid(), targetDistance),
                                               tolerance, pair->target.voxelSize())) {
            steps += int(morph.advect(time, time + 0.35));
            time += 0.35;
        }
    }
    countMorphResult(state, *field, pair->target, steps);
}

BENCHMARK(BM_OursSmoothStep)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_OpenVdbMeanCurvature)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_OursMorph)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(BM_OpenVdbMorph)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(BM_OursMorphReal)->DenseRange(0, 1)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);
BENCHMARK(BM_OpenVdbMorphReal)->DenseRange(0, 1)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

}  // namespace
