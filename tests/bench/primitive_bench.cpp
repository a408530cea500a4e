// SPDX-License-Identifier: Apache-2.0
// Stamping one point primitive (radius 16 voxels) into a sphere, beside OpenVDB's csgUnion with a
// createLevelSetSphere of the same radius, in one run.
// Run: build/tests/bench/primitive_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only
//
// BM_OursStamp/R       : rasterize the primitive over its own box, union into a radius-R sphere
// BM_OpenVdbCsgUnion/R : createLevelSetSphere(16) then tools::csgUnion into a radius-R sphere

#include "core/field/csg_combine.h"
#include "core/primitives/analytic_shapes.h"
#include "core/primitives/primitive_rasterizer.h"

#include <benchmark/benchmark.h>
#include <openvdb/tools/LevelSetSphere.h>

namespace {

using namespace sculpt;

constexpr double kStampRadius = 16.0;

/// A soft object whose surface is a ball of radius 16 voxels (f^-1(0.5) = R / 2).
PrimitiveSet stamp(double radiusVoxels)
{
    Primitive p;
    p.skeleton.points[0] = openvdb::Vec3d(radiusVoxels, 0.0, 0.0);
    p.kernel = Kernel{KernelType::SoftObject, 2.0 * kStampRadius, 1.0};
    return PrimitiveSet({p}, 0.5, false);
}

void BM_OursStamp(benchmark::State& state)
{
    const double radius = double(state.range(0));
    FieldImage sculpt = makeSphere(radius, 1.0);
    const PrimitiveSet set = stamp(radius);
    for (auto _ : state) {
        const FieldImage shape = rasterizePrimitives(set, sculpt.grid().transform());
        benchmark::DoNotOptimize(combine(sculpt, shape, CsgOperation::Union).leafCount());
    }
}

void BM_OpenVdbCsgUnion(benchmark::State& state)
{
    const double radius = double(state.range(0));
    FieldImage sculpt = makeSphere(radius, 1.0);
    for (auto _ : state) {
        auto ball = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(
            float(kStampRadius), openvdb::Vec3f(float(radius), 0.0f, 0.0f), 1.0f, 3.0f);
        combineWhole(sculpt.mutableGrid(), *ball, CsgOperation::Union);  // tools::csgUnion, in one unit
    }
}

BENCHMARK(BM_OursStamp)->Arg(256)->Arg(512)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_OpenVdbCsgUnion)->Arg(256)->Arg(512)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
