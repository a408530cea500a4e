// SPDX-License-Identifier: Apache-2.0
// The incremental block mesher beside OpenVDB's volumeToMesh, on level-set spheres.
// Run: build/tests/bench/mesher_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only
//
// BM_OursFull/R/B          : welded mesh with normals of a radius-R sphere, blocks of B voxels
// BM_VolumeToMesh/R        : openvdb::tools::volumeToMesh, adaptivity 0 (points and quads only)
// BM_OursIncremental/R     : re-mesh after one radius-16 stamp at the surface of a radius-R sphere
// BM_OursRebuild/R         : re-mesh of every block (no welding): the incremental path's baseline

#include "core/local/sphere_stamp.h"
#include "core/mesh/incremental_mesher.h"
#include "core/primitives/analytic_shapes.h"

#include <benchmark/benchmark.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <map>
#include <memory>

namespace {

using sculpt::FieldImage;

const FieldImage& sphere(int radiusVoxels)
{
    static std::map<int, std::unique_ptr<FieldImage>> cache;
    auto& slot = cache[radiusVoxels];
    if (!slot) slot = std::make_unique<FieldImage>(sculpt::makeSphere(radiusVoxels, 1.0));
    return *slot;
}

void BM_OursFull(benchmark::State& state)
{
    const FieldImage& field = sphere(int(state.range(0)));
    std::size_t triangles = 0, cacheBytes = 0;
    for (auto _ : state) {
        sculpt::IncrementalMesher mesher(int(state.range(1)));
        mesher.rebuild(field);
        const auto mesh = mesher.weldedMesh();
        triangles = mesh.triangles.size();
        cacheBytes = mesher.memoryBytes();
        benchmark::DoNotOptimize(mesh.positions.data());
    }
    state.counters["triangles"] = double(triangles);
    state.counters["cache_bytes_per_triangle"] = double(cacheBytes) / double(triangles);
}

void BM_VolumeToMesh(benchmark::State& state)
{
    const FieldImage& field = sphere(int(state.range(0)));
    std::size_t polygons = 0;
    for (auto _ : state) {
        std::vector<openvdb::Vec3s> points;
        std::vector<openvdb::Vec4I> quads;
        openvdb::tools::volumeToMesh(field.grid(), points, quads, 0.0);
        polygons = quads.size();
        benchmark::DoNotOptimize(points.data());
    }
    state.counters["triangles"] = double(2 * polygons);
}

void BM_OursRebuild(benchmark::State& state)
{
    const FieldImage& field = sphere(int(state.range(0)));
    sculpt::IncrementalMesher mesher;
    for (auto _ : state) mesher.rebuild(field);
}

void BM_OursIncremental(benchmark::State& state)
{
    const int radius = int(state.range(0));
    FieldImage field(sphere(radius).grid().deepCopy());
    sculpt::IncrementalMesher mesher;
    mesher.rebuild(field);
    const auto dirty = sculpt::stampSphere(field, {double(radius), 0.0, 0.0}, 16.0, sculpt::CsgMode::Add);
    std::size_t blocks = 0;
    for (auto _ : state) blocks = mesher.update(field, dirty);
    state.counters["blocks"] = double(blocks);
    state.counters["dirty_leaves"] = double(dirty.leafCount());
}

BENCHMARK(BM_OursFull)
    ->ArgsProduct({{64, 128, 256, 512}, {16}})
    ->Args({128, 8})
    ->Args({128, 32})
    ->Args({256, 8})
    ->Args({256, 32})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_VolumeToMesh)->Arg(64)->Arg(128)->Arg(256)->Arg(512)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_OursRebuild)->Arg(256)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_OursIncremental)->Arg(128)->Arg(256)->Arg(512)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
