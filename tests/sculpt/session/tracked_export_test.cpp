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

#include <cmath>
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
        EXPECT_TRUE(std::filesystem::exists(segmentPath(dir / "tracked", s, "ply")));
    }
    EXPECT_EQ(frames, 3);
}

}  // namespace
}  // namespace sculpt
