// Level-set motion beside OpenVDB's own tools, in one run.
// Run: build/tests/bench/motion_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only
//
// BM_OursSmoothStep/R        : one mean-curvature step of the whole band of a radius-R sphere
//                              (TVD-RK2, band rebuilt when beta t reaches h^2/2, i.e. every 3 steps)
// BM_OpenVdbMeanCurvature/R  : tools::LevelSetFilter::meanCurvature() (one step + track every step)
// BM_OursMorph / BM_OpenVdbMorph : sphere (radius 64) -> box until every surface point is within
//                              0.4 voxel of the box (checked every 4 steps / 4 CFL steps)
// BM_OursRegionSmoothStep/R  : one smoothing step limited to a radius-16 ball on a radius-R sphere

#include "core/motion/level_set_evolution.h"
#include "core/motion/morph.h"
#include "core/primitives/analytic_shapes.h"

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

void BM_OursRegionSmoothStep(benchmark::State& state)
{
    const double radius = double(state.range(0));
    FieldImage field = makeSphere(radius, 1.0);
    MotionTerms terms;
    terms.smooth = SmoothTerm{1.0, std::nullopt};
    LevelSetEvolution evolution(field, terms, {}, MotionRegion{{radius, 0.0, 0.0}, 16.0});
    for (auto _ : state) evolution.step();
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
            distance = surfaceDistance(field, box);
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
            distance = surfaceDistance(field, box);
        } while (distance > kToleranceVoxels && steps < 4000);
        return steps;
    });
}

BENCHMARK(BM_OursSmoothStep)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_OpenVdbMeanCurvature)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_OursRegionSmoothStep)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_OursMorph)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(BM_OpenVdbMorph)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

}  // namespace
