// SPDX-License-Identifier: Apache-2.0
// A tracked sequence written as files people play: the point cache and the glTF read back (the
// glTF by tinygltf, another implementation) with the vertex count, triangles and positions of
// the tracked mesh at every frame; `sculpt morph --tracked` writes them.

#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include "core/base/errors.h"
#include "core/io/point_cache_file.h"
#include "core/io/vdb_file.h"
#include "core/primitives/analytic_shapes.h"
#include "core/tracking/mesh_tracker.h"
#include "sculpt/session/tracked_export.h"
#include "tests/support/grid_builders.h"
#include "tests/support/run_sculpt.h"
#include "tests/support/temp_dir.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <tiny_gltf.h>

namespace sculpt {
namespace {

/// A sphere moved rigidly by a voxel a frame, tracked with the displacement known: one segment.
TrackedSequence trackedRigidMove(int frames)
{
    const FieldImage ball = makeSphere(12.0, 0.5);
    MeshTracker tracker(ball);
    TrackedSequence sequence;
    sequence.add(tracker.mesh());
    const openvdb::Vec3d step(0.125, 0.0, 0.0);  // a quarter voxel
    for (int k = 1; k <= 4 * (frames - 1); ++k) {
        tracker.step(test::translated(ball, step * k), [&](const openvdb::Vec3d&) { return step; });
        if (k % 4 == 0) sequence.add(tracker.mesh());
    }
    return sequence;
}

/// The floats of a glTF accessor (tightly packed, as ours are).
std::vector<float> floatsOf(const tinygltf::Model& model, int accessor)
{
    const tinygltf::Accessor& a = model.accessors.at(std::size_t(accessor));
    const tinygltf::BufferView& view = model.bufferViews.at(std::size_t(a.bufferView));
    const std::size_t components = a.type == TINYGLTF_TYPE_VEC3 ? 3 : 1;
    std::vector<float> values(a.count * components);
    std::memcpy(values.data(), model.buffers.at(std::size_t(view.buffer)).data.data() + view.byteOffset + a.byteOffset,
                values.size() * sizeof(float));
    return values;
}

TEST(TrackedExport, ThePointCacheAndTheGltfReadBackAsTheTrackedMeshAtEveryFrame)
{
    const int frames = 4;
    const TrackedSequence sequence = trackedRigidMove(frames);
    ASSERT_EQ(sequence.segments().size(), 1u);
    const TrackedSegment& segment = sequence.segments().front();
    ASSERT_EQ(segment.positions.size(), std::size_t(frames));
    test::TempDir dir;
    writeTrackedSequence(sequence, dir.path());

    const PointCache cache = readPointCache(segmentPath(dir.path(), 0, "pc2"));
    EXPECT_EQ(cache.samples, segment.positions);
    EXPECT_EQ(cache.startFrame, 0.0f);

    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::string error, warning;
    ASSERT_TRUE(loader.LoadBinaryFromFile(&model, &error, &warning, segmentPath(dir.path(), 0, "glb").string()))
        << error;
    ASSERT_EQ(model.meshes.size(), 1u);
    ASSERT_EQ(model.meshes[0].primitives.size(), 1u);
    const tinygltf::Primitive& primitive = model.meshes[0].primitives[0];
    const std::vector<float> base = floatsOf(model, primitive.attributes.at("POSITION"));
    const std::size_t vertices = segment.ids.size();
    ASSERT_EQ(base.size(), 3 * vertices);
    const tinygltf::Accessor& indices = model.accessors.at(std::size_t(primitive.indices));
    ASSERT_EQ(indices.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
    ASSERT_EQ(indices.count, 3 * segment.triangles.size());
    const tinygltf::BufferView& view = model.bufferViews.at(std::size_t(indices.bufferView));
    EXPECT_EQ(std::memcmp(model.buffers[0].data.data() + view.byteOffset, segment.triangles.data(), view.byteLength),
              0);
    ASSERT_EQ(primitive.targets.size(), std::size_t(frames - 1));
    for (int k = 0; k < frames; ++k) {
        std::vector<float> delta(base.size(), 0.0f);
        if (k > 0) delta = floatsOf(model, primitive.targets[std::size_t(k - 1)].at("POSITION"));
        double worst = 0.0;
        for (std::size_t v = 0; v < vertices; ++v)
            for (int c = 0; c < 3; ++c)
                worst =
                    std::max(worst, double(std::abs(base[3 * v + c] + delta[3 * v + c] - segment.positions[k][v][c])));
        EXPECT_LT(worst, 1e-5) << "frame " << k;
    }
    ASSERT_EQ(model.animations.size(), 1u);
    const tinygltf::AnimationSampler& sampler = model.animations[0].samplers.at(0);
    EXPECT_EQ(model.animations[0].channels.at(0).target_path, "weights");
    EXPECT_EQ(floatsOf(model, sampler.input).size(), std::size_t(frames));
    EXPECT_EQ(floatsOf(model, sampler.output).size(), std::size_t(frames * (frames - 1)));
}

/// Every number in `text` (USD's lists and tuples are numbers between brackets and commas).
std::vector<double> numbersIn(const std::string& text)
{
    std::vector<double> numbers;
    for (const char* p = text.c_str(); *p;) {
        char* end = nullptr;
        const double value = std::strtod(p, &end);
        if (end != p && (std::isdigit(static_cast<unsigned char>(*p)) || *p == '-')) {
            numbers.push_back(value);
            p = end;
        } else {
            ++p;
        }
    }
    return numbers;
}

/// A `.usda` layer's lines that start (after indentation) with `prefix`, without the prefix.
std::vector<std::string> usdLines(const std::filesystem::path& path, const std::string& prefix)
{
    std::ifstream in(path);
    std::vector<std::string> found;
    for (std::string line; std::getline(in, line);) {
        const std::size_t start = line.find_first_not_of(' ');
        if (start != std::string::npos && line.compare(start, prefix.size(), prefix) == 0)
            found.push_back(line.substr(start + prefix.size()));
    }
    return found;
}

/// The time samples of attribute `declaration`: per frame, its numbers (the frame number first).
std::vector<std::vector<double>> timeSamples(const std::filesystem::path& path, const std::string& declaration)
{
    std::ifstream in(path);
    std::vector<std::vector<double>> samples;
    bool inside = false;
    for (std::string line; std::getline(in, line);) {
        if (line.find(declaration + ".timeSamples") != std::string::npos) inside = true;
        else if (inside && line.find('}') != std::string::npos) break;
        else if (inside) samples.push_back(numbersIn(line));
    }
    return samples;
}

TEST(TrackedExport, TheUsdLayerHoldsTheFacesPointsVelocitiesAndIdsOfEveryFrame)
{
    const int frames = 4;
    const TrackedSequence sequence = trackedRigidMove(frames);
    const TrackedSegment& segment = sequence.segments().front();
    test::TempDir dir;
    writeTrackedSequence(sequence, dir.path(), 24.0);
    const std::filesystem::path usda = segmentPath(dir.path(), 0, "usda");

    ASSERT_EQ(usdLines(usda, "#usda 1.0").size(), 1u);
    EXPECT_EQ(numbersIn(usdLines(usda, "endTimeCode").at(0)), std::vector<double>{double(frames - 1)});
    const std::vector<double> indices = numbersIn(usdLines(usda, "int[] faceVertexIndices").at(0));
    ASSERT_EQ(indices.size(), 3 * segment.triangles.size());
    for (std::size_t t = 0; t < segment.triangles.size(); ++t)
        for (std::size_t k = 0; k < 3; ++k) ASSERT_EQ(indices[3 * t + k], double(segment.triangles[t][k]));
    const std::vector<double> ids = numbersIn(usdLines(usda, "int[] primvars:sculptVertexId").at(0));
    EXPECT_EQ(ids, std::vector<double>(segment.ids.begin(), segment.ids.end()));

    const auto points = timeSamples(usda, "point3f[] points"), velocities = timeSamples(usda, "vector3f[] velocities");
    ASSERT_EQ(points.size(), std::size_t(frames));
    ASSERT_EQ(velocities.size(), std::size_t(frames));
    const std::size_t vertices = segment.ids.size();
    for (int k = 0; k < frames; ++k) {
        ASSERT_EQ(points[k].size(), 1 + 3 * vertices);
        EXPECT_EQ(points[k][0], double(k)) << "the time code";
        for (std::size_t v = 0; v < vertices; ++v)
            for (std::size_t c = 0; c < 3; ++c) ASSERT_EQ(float(points[k][1 + 3 * v + c]), segment.positions[k][v][c]);
    }
    // Velocities in mm/s: the sphere moves half a millimetre a frame along x, 12 mm/s at 24 fps.
    double meanX = 0.0;
    for (std::size_t v = 0; v < vertices; ++v) meanX += velocities[1][1 + 3 * v] / double(vertices);
    EXPECT_NEAR(meanX, 12.0, 0.05);
    const double dt = 1.0 / 24.0;
    for (std::size_t v = 0; v < vertices; ++v)
        EXPECT_NEAR(velocities[2][1 + 3 * v + 1], (points[3][1 + 3 * v + 1] - points[1][1 + 3 * v + 1]) / (2 * dt),
                    1e-3);
}

TEST(TrackedExport, APointCacheOfTheWrongSizeIsRefusedNamingTheFile)
{
    test::TempDir dir;
    const PointCache cache{0.0f, 1.0f, {{{1, 2, 3}, {4, 5, 6}}, {{7, 8, 9}, {10, 11, 12}}}};
    writePointCache(cache, dir / "a.pc2");
    EXPECT_EQ(readPointCache(dir / "a.pc2").samples, cache.samples);
    std::filesystem::resize_file(dir / "a.pc2", std::filesystem::file_size(dir / "a.pc2") - 4);
    try {
        readPointCache(dir / "a.pc2");
        FAIL() << "a cut point cache was read";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("a.pc2"), std::string::npos) << e.what();
    }
}

TEST(TrackedExport, SculptMorphTrackedWritesEverySegmentAndListsThem)
{
    test::TempDir dir;
    writeFieldImage(makeSphere(12.0, 0.5), dir / "ball.vdb");
    writeFieldImage(makeBox(10.0, 0.5), dir / "box.vdb");
    const auto run =
        test::runSculpt("morph ball.vdb box.vdb --frames 3 -o frames --tracked tracked", dir.path().string());
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("tracked mesh: "), std::string::npos) << run.out;
    std::ifstream in(dir / "tracked" / "segments.json");
    const nlohmann::json list = nlohmann::json::parse(in);
    EXPECT_EQ(list["frames"], 3);
    ASSERT_GE(list["segments"].size(), 1u);
    int frames = 0;
    for (std::size_t s = 0; s < list["segments"].size(); ++s) {
        const nlohmann::json& segment = list["segments"][s];
        EXPECT_EQ(segment["first_frame"], frames);
        frames += segment["frames"].get<int>();
        const PointCache cache = readPointCache(segmentPath(dir / "tracked", s, "pc2"));
        ASSERT_EQ(cache.samples.size(), segment["frames"].get<std::size_t>());
        EXPECT_EQ(cache.samples[0].size(), segment["vertices"].get<std::size_t>());
        EXPECT_TRUE(std::filesystem::exists(segmentPath(dir / "tracked", s, "glb")));
        EXPECT_TRUE(std::filesystem::exists(segmentPath(dir / "tracked", s, "usda")));
        EXPECT_TRUE(std::filesystem::exists(segmentPath(dir / "tracked", s, "ply")));
    }
    EXPECT_EQ(frames, 3);
}

// A morph that fails after it wrote frames (here the tracked list cannot be written: a directory
// stands where it goes) takes back every file it wrote and the directory it made; what was there
// before stays.
TEST(TrackedExport, AMorphThatFailsAfterWritingFramesLeavesNoOutput)
{
    test::TempDir dir;
    writeFieldImage(makeSphere(12.0, 0.5), dir / "ball.vdb");
    writeFieldImage(makeBox(10.0, 0.5), dir / "box.vdb");
    std::filesystem::create_directories(dir / "tracked" / "segments.json");
    const auto run = test::runSculpt("morph ball.vdb box.vdb --frames 3 --mesh ply -o frames --tracked tracked",
                                     dir.path().string());
    EXPECT_NE(run.exitCode, 0);
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "frames"));
    EXPECT_EQ(test::TempDir::entriesOf(dir / "tracked"), std::vector<std::string>{"segments.json"});
    EXPECT_TRUE(std::filesystem::is_directory(dir / "tracked" / "segments.json"));
}

}  // namespace
}  // namespace sculpt
