// SPDX-License-Identifier: Apache-2.0
// Building the starting sphere: our analytic rasterizer versus OpenVDB's createLevelSetSphere.
// Run: build/tests/bench/shape_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only

#include "core/primitives/analytic_shapes.h"

#include <benchmark/benchmark.h>
#include <openvdb/tools/LevelSetSphere.h>

namespace {

void BM_SculptSphere(benchmark::State& state)
{
    const double radiusVoxels = double(state.range(0));
    for (auto _ : state) {
        auto field = sculpt::makeSphere(radiusVoxels, 1.0);
        benchmark::DoNotOptimize(field.grid().activeVoxelCount());
    }
}

void BM_OpenVdbSphere(benchmark::State& state)
{
    const float radiusVoxels = float(state.range(0));
    for (auto _ : state) {
        auto grid =
            openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(radiusVoxels, openvdb::Vec3f(0.0f), 1.0f, 3.0f);
        benchmark::DoNotOptimize(grid->activeVoxelCount());
    }
}

BENCHMARK(BM_SculptSphere)->Arg(64)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OpenVdbSphere)->Arg(64)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond);

}  // namespace
