// SPDX-License-Identifier: Apache-2.0
// Ray-traced final images: ours (colour, depth and normals per pixel) beside OpenVDB's own
// tools::rayTrace (RayTracer.h, DiffuseShader, colour only) on the same grid and camera, in one
// run; and a 4-sample 1920x1080 render of the demo's sculpted face.
// Run: build/tests/bench/render_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only
//
// BM_OpenVdbRayTrace       1024x1024, one sample, a sphere of radius 256 voxels seen from 800 voxels
// BM_OursRender/0          the same image, no ambient occlusion (what OpenVDB's diffuse shader does)
// BM_OursRender/8          the same with 8 occlusion rays per hit (our default)
// BM_OursFace              out/face.vdb (made by scripts/demo.sh) at 1920x1080, 4 samples, defaults

#include "core/io/vdb_file.h"
#include "core/render/ray_tracer.h"

#include <benchmark/benchmark.h>
#include <openvdb/tools/LevelSetSphere.h>
#include <openvdb/tools/RayTracer.h>

#include <filesystem>

namespace {

using openvdb::Vec3d;

constexpr int kSide = 1024;
constexpr double kDistance = 800.0;
// OpenVDB's default camera: focal length 50, aperture 41.2136 (horizontal field of view).
const double kFovDegrees = 2.0 * std::atan(0.5 * 41.2136 / 50.0) * 180.0 / M_PI;

const sculpt::FieldImage& sphere()
{
    static const sculpt::FieldImage field = [] {
        auto grid = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(256.0f, openvdb::Vec3f(0.0f), 1.0f, 3.0f);
        return sculpt::FieldImage(grid);
    }();
    return field;
}

void BM_OpenVdbRayTrace(benchmark::State& state)
{
    const openvdb::FloatGrid& grid = sphere().grid();
    for (auto _ : state) {
        openvdb::tools::Film film(kSide, kSide);
        openvdb::tools::PerspectiveCamera camera(film, Vec3d(0.0), Vec3d(0.0, 0.0, kDistance));
        openvdb::tools::DiffuseShader<> shader;
        openvdb::tools::rayTrace(grid, shader, camera, 1, 0, true);
        benchmark::DoNotOptimize(film.pixels());
    }
}

void BM_OursRender(benchmark::State& state)
{
    sculpt::Camera camera;
    camera.position = Vec3d(0.0, 0.0, kDistance);
    camera.fovDegrees = kFovDegrees;
    sculpt::RenderOptions options;
    options.width = options.height = kSide;
    options.samples = 1;
    options.occlusionRays = int(state.range(0));
    for (auto _ : state) {
        sculpt::RenderReport report;
        const sculpt::RenderedImage image = sculpt::renderField(sphere(), camera, options, report);
        benchmark::DoNotOptimize(image.rgba.data());
    }
}

void BM_OursFace(benchmark::State& state)
{
    const std::filesystem::path path = std::filesystem::path(SCULPT_SOURCE_DIR) / "out" / "face.vdb";
    if (!std::filesystem::exists(path)) {
        state.SkipWithError("run scripts/demo.sh first: it writes out/face.vdb");
        return;
    }
    const sculpt::FieldImage face = sculpt::readFieldImage(path);
    sculpt::RenderOptions options;
    options.width = 1920;
    options.height = 1080;
    options.samples = 4;
    const sculpt::Camera camera =
        sculpt::framingCamera(sculpt::SurfaceExtent(face), double(options.width) / options.height);
    for (auto _ : state) {
        sculpt::RenderReport report;
        const sculpt::RenderedImage image = sculpt::renderField(face, camera, options, report);
        benchmark::DoNotOptimize(image.rgba.data());
    }
}

BENCHMARK(BM_OpenVdbRayTrace)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_OursRender)->Arg(0)->Arg(8)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_OursFace)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);

}  // namespace
