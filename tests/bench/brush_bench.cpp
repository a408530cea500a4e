// SPDX-License-Identifier: Apache-2.0
// Per-stamp latency of the brushes (stamp + local redistancing + incremental re-mesh of the
// touched blocks), radius 16 voxels, on spheres of radius 128, 256 and 512 voxels, beside the
// naive path (tools::csgUnion of a stamp sphere, then a full tools::volumeToMesh) in one run.
// Run: build/tests/bench/brush_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only
//
// BM_Stamp/tool/R     : one stamp of `tool` (0 add, 1 inflate, 2 smooth, 3 carve, 4 flatten,
//                       5 grab, 6 pinch), strength 0.5, stamps walking along one long stroke;
//                       counter undo_bytes = the stroke's journal bytes per stamp
// BM_NaiveUnion/R     : createLevelSetSphere(16) + csgUnion into the sphere + volumeToMesh

#include "core/brushes/brush.h"
#include "core/field/csg_combine.h"
#include "core/field/leaf_journal.h"
#include "core/mesh/incremental_mesher.h"
#include "core/primitives/analytic_shapes.h"

#include <benchmark/benchmark.h>
#include <openvdb/tools/LevelSetSphere.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <cmath>

namespace {

using namespace sculpt;

constexpr double kBrushRadius = 16.0;
constexpr BrushTool kTools[] = {BrushTool::Add,     BrushTool::Inflate, BrushTool::Smooth, BrushTool::Carve,
                                BrushTool::Flatten, BrushTool::Grab,    BrushTool::Pinch};

/// Stamp i of a stroke a quarter brush radius apart, spiralling up from latitude -60 degrees by
/// three brush radii per turn: every stamp meets fresh surface, as a sculptor's strokes do.
openvdb::Vec3d onStroke(double radius, int i)
{
    const double arc = 0.25 * kBrushRadius * i;
    const double turns = arc / (2.0 * M_PI * radius);
    const double latitude = -M_PI / 3.0 + turns * 3.0 * kBrushRadius / radius;
    const double longitude = arc / (radius * std::cos(latitude));
    return openvdb::Vec3d(radius * std::cos(latitude) * std::cos(longitude),
                          radius * std::cos(latitude) * std::sin(longitude), radius * std::sin(latitude));
}

void BM_Stamp(benchmark::State& state)
{
    const BrushTool tool = kTools[state.range(0)];
    const double radius = double(state.range(1));
    FieldImage field = makeSphere(radius, 1.0);
    IncrementalMesher mesher;
    mesher.rebuild(field);
    field.takeDirtyRegion();
    BrushSettings brush;
    brush.tool = tool;
    brush.radiusWorld = kBrushRadius;
    brush.strength = 0.5;
    LeafJournal journal;
    int i = 0;
    for (auto _ : state) {
        BrushStamp stamp;
        stamp.centreWorld = onStroke(radius, i + 1);
        stamp.previousWorld = onStroke(radius, i);
        applyStamp(field, brush, stamp, &journal);
        mesher.update(field, field.takeDirtyRegion());
        ++i;
    }
    state.counters["undo_bytes"] = double(journal.memoryBytes()) / double(std::max(i, 1));
    state.SetLabel(brushToolName(tool));
}

void BM_NaiveUnion(benchmark::State& state)
{
    const double radius = double(state.range(0));
    FieldImage field = makeSphere(radius, 1.0);
    int i = 0;
    for (auto _ : state) {
        const openvdb::Vec3d at = onStroke(radius, ++i);
        auto ball = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(
            float(kBrushRadius * 0.5), openvdb::Vec3f(at), 1.0f, 3.0f);  // add's ball: radius x strength
        combineWhole(field.mutableGrid(), *ball, CsgOperation::Union);   // tools::csgUnion, in one unit
        std::vector<openvdb::Vec3s> points;
        std::vector<openvdb::Vec3I> triangles;
        std::vector<openvdb::Vec4I> quads;
        openvdb::tools::volumeToMesh(field.grid(), points, triangles, quads, 0.0, 0.0);
        benchmark::DoNotOptimize(points.size());
    }
}

BENCHMARK(BM_Stamp)
    ->ArgsProduct({{0, 1, 2}, {128, 256, 512}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(1.0);
BENCHMARK(BM_Stamp)->ArgsProduct({{3, 4, 5, 6}, {256}})->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0);
BENCHMARK(BM_NaiveUnion)->Arg(128)->Arg(256)->Arg(512)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

}  // namespace
