// SPDX-License-Identifier: Apache-2.0
// Masks, cuts and hollowing beside their references, in one run (issue 34's figures):
// - one smoothing step of the whole model with half its surface masked, against the same step
//   unmasked: what reading the mask costs;
// - a lasso cut through the model (applyPrism: the prism's band within the model's reach, then
//   csgDifference) against OpenVDB's own route for the same prism: its mesh (the lasso's outline
//   at the model's nearest and farthest depths) to a level set (meshToLevelSet, through the mesh
//   import), then csgDifference (through combineWhole: both instantiated once, in core);
// - hollowing the model into a 2 mm inside shell with drain holes;
// - each mask selection (the lasso's prism, cavities, walls thinner than 2 mm, the island at a
//   surface point), next to the smoothing step.
// The model: $SCULPT_BENCH_MODEL (a .vdb, e.g. ch2better imported at 0.25 mm:
// `sculpt import /usr/share/mricron/templates/ch2better.nii.gz --largest-component
// --voxel-size 0.25 -o ch2.vdb`), else the clay ball (radius 50 at 0.5).

#include "core/field/csg_combine.h"
#include "core/field/leaf_journal.h"
#include "core/io/mesh_import.h"
#include "core/io/vdb_file.h"
#include "core/masks/mask_edit.h"
#include "core/masks/mask_selection.h"
#include "core/motion/surface_flows.h"
#include "core/primitives/analytic_shapes.h"
#include "core/solids/hollow.h"
#include "core/solids/prism_cut.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <memory>

namespace sculpt {
namespace {

const FieldImage& model()
{
    static const std::unique_ptr<FieldImage> field = [] {
        const char* path = std::getenv("SCULPT_BENCH_MODEL");
        return std::make_unique<FieldImage>(path ? readFieldImage(path) : makeSphere(50.0, 0.5));
    }();
    return *field;
}

openvdb::BBoxd worldBox(const FieldImage& field)
{
    openvdb::CoordBBox leaves;
    field.grid().tree().evalLeafBoundingBox(leaves);
    return field.grid().transform().indexToWorld(leaves);
}

/// The model with the half x < centre masked (by closest surface points).
FieldImage halfMasked()
{
    FieldImage field = model().deepCopy();
    const double middle = worldBox(field).getCenter().x();
    rewriteMask(field, maskDomain(field), nullptr, [middle](const openvdb::Coord& ijk, const MaskSite& site) {
        return site.footWorld(ijk).x() < middle ? 1.0 : 0.0;
    });
    return field;
}

void BM_SmoothStep(benchmark::State& state)
{
    const FieldImage start = state.range(0) ? halfMasked() : model().deepCopy();
    for (auto _ : state) {
        state.PauseTiming();
        FieldImage field = start.deepCopy();
        state.ResumeTiming();
        smooth(field, 1);
        benchmark::DoNotOptimize(field.grid().activeVoxelCount());
    }
    state.SetLabel(state.range(0) ? "half masked" : "unmasked");
    state.counters["voxels"] = double(start.grid().activeVoxelCount());
}
BENCHMARK(BM_SmoothStep)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

/// An ellipse round the model's right third, seen from the front (+z), parallel rays, drawn
/// with `points` points.
ViewPrism lasso(int points = 64)
{
    const openvdb::BBoxd box = worldBox(model());
    const openvdb::Vec3d c = box.getCenter(), e = box.extents();
    ViewPrism prism;
    prism.viewFromWorld.setTranslation(openvdb::Vec3d(0.0, 0.0, -(box.max().z() + 10.0)));
    for (int i = 0; i < points; ++i) {
        const double a = 2.0 * M_PI * i / points;
        prism.polygon.emplace_back(c.x() + e.x() * (0.35 + 0.2 * std::cos(a)), c.y() + 0.4 * e.y() * std::sin(a));
    }
    return prism;
}

/// The same lasso drawn with 64 points, the 12,000 of a long careful stroke, and the stroke
/// scripts' limit of 100,000: the cost should follow the voxels cut, not the points.
void BM_LassoCut(benchmark::State& state)
{
    const ViewPrism prism = lasso(int(state.range(0)));
    for (auto _ : state) benchmark::DoNotOptimize(applyPrism(model(), prism, PrismMode::Cut).grid().activeVoxelCount());
    state.counters["voxels"] = double(model().grid().activeVoxelCount());
    state.counters["points"] = double(prism.polygon.size());
}
BENCHMARK(BM_LassoCut)->Arg(64)->Arg(12000)->Arg(100000)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

void BM_LassoCutOpenVdbMeshToLevelSetAndCsgDifference(benchmark::State& state)
{
    const ViewPrism prism = lasso();
    const openvdb::BBoxd box = worldBox(model());
    const double front = box.max().z() + 1.0, back = box.min().z() - 1.0;
    TriangleMesh prismMesh;
    for (const double z : {front, back})
        for (const openvdb::Vec2d& p : prism.polygon)
            prismMesh.positions.push_back({float(p.x()), float(p.y()), float(z)});
    const auto n = std::uint32_t(prism.polygon.size());
    for (std::uint32_t i = 1; i + 1 < n; ++i) {  // the outline is convex: fans close both ends
        prismMesh.triangles.push_back({0, i + 1, i});
        prismMesh.triangles.push_back({n, n + i, n + i + 1});
    }
    for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint32_t j = (i + 1) % n;
        prismMesh.triangles.push_back({i, j, n + j});
        prismMesh.triangles.push_back({i, n + j, n + i});
    }
    const FieldImage& field = model();
    for (auto _ : state) {
        // tools::meshToLevelSet, as the mesh import calls it (one unit).
        const openvdb::FloatGrid::Ptr tool = meshToField(prismMesh, field.voxelSize()).mutableGridPtr();
        openvdb::FloatGrid::Ptr result = field.grid().deepCopy();
        combineWhole(*result, *tool, CsgOperation::Difference);  // tools::csgDifference, in one unit
        benchmark::DoNotOptimize(result->activeVoxelCount());
    }
}
BENCHMARK(BM_LassoCutOpenVdbMeshToLevelSetAndCsgDifference)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(3);

void BM_Hollow(benchmark::State& state)
{
    HollowOptions options;
    options.thicknessWorld = 2.0;
    for (auto _ : state) {
        HollowResult shell = hollow(model(), options);
        cutDrainHoles(shell.field, drainHolesUnder(shell.cavityBottoms, {0, 0, 1}, 2.0, 1.5));
        benchmark::DoNotOptimize(shell.field.grid().activeVoxelCount());
    }
}
BENCHMARK(BM_Hollow)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);

/// A point on the model's surface: the first band voxel within half a voxel of it.
openvdb::Vec3d surfacePoint(const FieldImage& field)
{
    for (auto it = field.grid().cbeginValueOn(); it; ++it)
        if (std::abs(*it) < 0.5 * field.voxelSize()) return field.grid().transform().indexToWorld(it.getCoord());
    return openvdb::Vec3d(0.0);
}

void BM_MaskSelection(benchmark::State& state)
{
    MaskSelection selection;
    selection.kind = MaskSelectionKind(state.range(0));
    selection.prism = lasso();
    selection.creaseRadiusWorld = 4.0 * model().voxelSize();
    selection.thicknessWorld = 2.0;
    selection.point = surfacePoint(model());
    for (auto _ : state) {
        state.PauseTiming();
        FieldImage field = model().deepCopy();
        state.ResumeTiming();
        applyMaskSelection(field, selection, nullptr);
        benchmark::DoNotOptimize(field.mask());
    }
    state.SetLabel(maskSelectionName(selection.kind));
}
BENCHMARK(BM_MaskSelection)->DenseRange(0, 3)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);

}  // namespace
}  // namespace sculpt
