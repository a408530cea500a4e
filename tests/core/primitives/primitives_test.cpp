// SPDX-License-Identifier: Apache-2.0
// Implicit primitives: kernels, lone primitives against analytic shapes, blending graph, CSG.

#include "core/base/errors.h"
#include "core/field/csg_combine.h"
#include "core/field/grid_checksum.h"
#include "core/mesh/field_measures.h"
#include "core/primitives/analytic_shapes.h"
#include "core/primitives/primitive_rasterizer.h"
#include "core/primitives/scene_file.h"
#include "tests/support/progress_log.h"
#include "tests/support/surface_stats.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace sculpt {
namespace {

constexpr double kPi = 3.14159265358979323846;
const KernelType kAllKernels[] = {KernelType::BlobbyMolecule, KernelType::Metaball, KernelType::SoftObject};

openvdb::math::Transform::Ptr voxels(double h) { return openvdb::math::Transform::createLinearTransform(h); }

Primitive point(const openvdb::Vec3d& at, KernelType kernel, double radius, std::vector<int> neighbours = {})
{
    Primitive p;
    p.skeleton.points[0] = at;
    p.kernel = Kernel{kernel, radius, 1.0};
    p.neighbours = std::move(neighbours);
    return p;
}

TEST(FieldKernels, ContinuousAtRadiusZeroBeyondAndDecreasing)
{
    for (KernelType type : kAllKernels) {
        const Kernel k{type, 2.0, 1.5};
        SCOPED_TRACE(kernelName(type));
        EXPECT_DOUBLE_EQ(k.value(0.0), 1.5);
        EXPECT_NEAR(k.value(2.0 - 1e-7), 0.0, 2e-4 * 1.5);  // blobby: e^-9, the others 0
        EXPECT_EQ(k.value(2.0), 0.0);
        EXPECT_EQ(k.value(7.0), 0.0);
        for (double r = 0.0; r < 2.0; r += 0.01) EXPECT_LE(k.value(r + 0.01), k.value(r)) << r;
        EXPECT_NEAR(k.value(k.inverse(0.5)), 0.5, 1e-9);
    }
    const Kernel metaball{KernelType::Metaball, 3.0, 1.0};  // the two pieces meet at R/3
    EXPECT_NEAR(metaball.value(1.0 - 1e-9), metaball.value(1.0 + 1e-9), 1e-8);
}

class LonePoint : public ::testing::TestWithParam<KernelType> {};

TEST_P(LonePoint, IsASphereOfRadiusInverseIso)
{
    const double h = 0.25, iso = 0.5;
    const PrimitiveSet set({point({1.0, -2.0, 0.5}, GetParam(), 6.0)}, iso, false);
    const FieldImage field = rasterizePrimitives(set, *voxels(h));
    const double expected = set.primitives()[0].kernel.inverse(iso);
    const test::RadiusStats r = test::surfaceRadius(field, {1.0, -2.0, 0.5});
    EXPECT_NEAR(r.min, expected, 0.5 * h);
    EXPECT_NEAR(r.max, expected, 0.5 * h);
}

INSTANTIATE_TEST_SUITE_P(Kernels, LonePoint, ::testing::ValuesIn(kAllKernels),
                         [](const auto& test) { return std::string(kernelName(test.param)).substr(0, 4); });

TEST(Primitives, SegmentMakesACapsule)
{
    Primitive bone;
    bone.skeleton.type = SkeletonType::Segment;
    bone.skeleton.points = {openvdb::Vec3d(-5, 0, 0), openvdb::Vec3d(5, 0, 0), openvdb::Vec3d(0.0)};
    bone.kernel = Kernel{KernelType::SoftObject, 6.0, 1.0};
    const PrimitiveSet set({bone}, 0.5, false);
    const double r = bone.kernel.inverse(0.5), length = 10.0;
    const double capsule = kPi * r * r * length + 4.0 / 3.0 * kPi * r * r * r;
    EXPECT_NEAR(measureField(rasterizePrimitives(set, *voxels(0.25))).volume, capsule, 0.02 * capsule);
}

/// Volume of two balls of radius r whose centres are d apart (d < 2r).
double twoBallsVolume(double r, double d)
{
    const double lens = kPi * (4.0 * r + d) * (2.0 * r - d) * (2.0 * r - d) / 12.0;
    return 2.0 * 4.0 / 3.0 * kPi * r * r * r - lens;
}

TEST(Primitives, NeighboursFuseNonNeighboursMeetInACrease)
{
    const double h = 0.25, d = 7.0;
    const auto pair = [&](bool neighbours) {
        return PrimitiveSet(
            {point({-d / 2, 0, 0}, KernelType::SoftObject, 8.0, neighbours ? std::vector<int>{1} : std::vector<int>{}),
             point({d / 2, 0, 0}, KernelType::SoftObject, 8.0)},
            0.5, true);
    };
    const double r = Kernel{KernelType::SoftObject, 8.0, 1.0}.inverse(0.5);  // 4: the balls overlap
    const FieldMeasures fused = measureField(rasterizePrimitives(pair(true), *voxels(h)));
    const FieldMeasures creased = measureField(rasterizePrimitives(pair(false), *voxels(h)));
    EXPECT_EQ(fused.components, 1);
    EXPECT_EQ(fused.eulerCharacteristic, 2);
    EXPECT_EQ(creased.components, 1);
    EXPECT_EQ(creased.eulerCharacteristic, 2);
    EXPECT_NEAR(creased.volume, twoBallsVolume(r, d), 0.01 * twoBallsVolume(r, d));  // no bridge
    EXPECT_GT(fused.volume, 1.05 * creased.volume);                                  // a bridge
}

TEST(Primitives, ChainEndsTouchWithoutFusing)
{
    const Scene chain = readScene(SCULPT_DATA_DIR "/scenes/chain.json");
    const auto& links = chain.primitives.primitives();
    const double h = 0.25;
    FieldImage whole = rasterizePrimitives(chain.primitives, *voxels(h));
    // Split where the graph forbids blending: {a, b, c} and {b, c, d} blend exactly as the chain.
    auto part = [&](std::vector<int> ids) {
        std::vector<Primitive> ps;
        for (int i : ids) {
            Primitive p = links[size_t(i)];
            p.neighbours.clear();
            ps.push_back(p);
        }
        ps[0].neighbours = {1};
        ps[1].neighbours = {2};
        return rasterizePrimitives(PrimitiveSet(ps, chain.primitives.iso(), true), *voxels(h));
    };
    FieldImage parts = part({0, 1, 2});
    combine(parts, part({1, 2, 3}), CsgOperation::Union);
    const double v = measureField(whole).volume, vParts = measureField(parts).volume;
    EXPECT_NEAR(v, vParts, 0.01 * vParts);
    // The ends touch (a ring: Euler 0) in a crease; summing every link instead fuses the ends
    // and fills the ring's hole (Euler 2).
    EXPECT_EQ(measureField(whole).eulerCharacteristic, 0);
    const PrimitiveSet summed(links, chain.primitives.iso(), false);
    EXPECT_EQ(measureField(rasterizePrimitives(summed, *voxels(h))).eulerCharacteristic, 2);
}

TEST(Primitives, CsgChangesVolumeAsTheShapesSay)
{
    const double h = 0.25, a = 6.0;
    const PrimitiveSet ball({point({a, 0, 0}, KernelType::SoftObject, 8.0)}, 0.5, false);
    const double r = ball.primitives()[0].kernel.inverse(0.5);  // 4, centred on the box's face
    const double box = 8 * a * a * a, half = 2.0 / 3.0 * kPi * r * r * r;
    auto run = [&](CsgOperation op) {
        FieldImage sculpt = makeBox(a, h);
        combine(sculpt, rasterizePrimitives(ball, sculpt.grid().transform()), op);
        return measureField(sculpt).volume;
    };
    EXPECT_NEAR(run(CsgOperation::Union), box + half, 0.01 * (box + half));
    EXPECT_NEAR(run(CsgOperation::Difference), box - half, 0.01 * (box - half));
    EXPECT_NEAR(run(CsgOperation::Intersection), half, 0.02 * half);
    EXPECT_NEAR(run(CsgOperation::Replace), 2 * half, 0.02 * 2 * half);
}

TEST(Primitives, SmallPrimitiveTouchesOnlyItsBox)
{
    FieldImage sculpt = makeSphere(40.0, 0.5);
    const PrimitiveSet blob({point({40.0, 0, 0}, KernelType::Metaball, 3.0)}, 0.5, false);
    const FieldImage shape = rasterizePrimitives(blob, sculpt.grid().transform());
    sculpt.takeDirtyRegion();
    const DirtyRegion dirty = combine(sculpt, shape, CsgOperation::Union);
    EXPECT_FALSE(dirty.empty());
    EXPECT_LT(dirty.leafCount(), 40u);
    openvdb::CoordBBox box = sculpt.grid().transform().worldToIndexCellCentered(blob.influence(0));
    box.expand(int(sculpt.halfWidthVoxels()) + 2 + 8);
    for (const auto& leaf : dirty.leafOrigins()) EXPECT_TRUE(box.isInside(leaf)) << leaf;
}

TEST(SceneFile, BadScenesNameThePrimitiveAndField)
{
    auto expectError = [](const std::string& text, const std::string& mentions) {
        try {
            parseScene(text, "scene.json");
            FAIL() << "accepted: " << text;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(mentions), std::string::npos) << e.what();
        }
    };
    const std::string point = R"("skeleton": {"type": "point", "position": [0, 0, 0]})";
    expectError(R"({"primitives": [{"kernel": "gauss", "radius": 1, )" + point + "}]}", "gauss");
    expectError(R"({"primitives": [{"name": "x", "kernel": "metaball", "radius": 0, )" + point + "}]}",
                "primitive 0 ('x'): radius");
    expectError(R"({"primitives": [{"kernel": "metaball", "radius": 1, "skeleton": {"type": "cone"}}]})", "cone");
    expectError(R"({"primitives": [{"kernel": "metaball", "radius": 1, "neighbours": ["ghost"], )" + point + "}]}",
                "ghost");
    expectError(
        R"({"primitives": [{"kernel": "metaball", "radius": 1, "skeleton": {"type": "segment", "from": [1, 1, 1], "to": [1, 1, 1]}}]})",
        "degenerate segment");
    expectError(
        R"({"primitives": [{"kernel": "metaball", "radius": 1, "skeleton": {"type": "triangle", "points": [[0,0,0],[1,1,1],[2,2,2]]}}]})",
        "degenerate triangle");
    expectError(R"({"primitives": [{"kernel": "metaball", )" + point + "}]}", "missing field 'radius'");
    expectError(R"({"primitives": [)", "malformed JSON");
    expectError(R"({"primitives": [{"kernel": "metaball", "radius": 1, "strength": 0.2, )" + point + "}]}", "strength");
}

TEST(SceneFile, ExampleScenesBuild)
{
    for (const char* name : {"snowman", "chain", "carved_box"}) {
        const Scene scene = readScene(std::string(SCULPT_DATA_DIR "/scenes/") + name + ".json");
        const FieldImage field = rasterizePrimitives(scene.primitives, *voxels(scene.voxelSize.value_or(0.5)));
        EXPECT_EQ(measureField(field).components, 1) << name;
    }
}

TEST(SceneFile, AWrittenSceneReadsBackToTheSameGrid)
{
    // Every skeleton, a rotated box, the chain's neighbours graph with unnamed primitives.
    const std::string rotated =
        R"({"iso": 0.4, "operation": "difference", "voxel_size": 0.3, "primitives": [
        {"kernel": "metaball", "radius": 3, "strength": 0.9, "skeleton": {"type": "segment", "from": [0, 0, 0], "to": [2, 1, 0]}},
        {"kernel": "blobby-molecule", "radius": 2.5, "skeleton": {"type": "triangle", "points": [[0, 0, 1], [2, 0, 1], [0, 2, 1.5]]}},
        {"name": "b", "kernel": "soft-object", "radius": 2, "skeleton": {"type": "box", "center": [1, 1, 1],
         "half_extents": [1, 0.5, 0.25], "rotation_degrees": [30, -20, 75]}}]})";
    std::vector<Scene> scenes{parseScene(rotated, "rotated")};
    for (const char* name : {"snowman", "chain", "carved_box", "ear"}) {
        scenes.push_back(readScene(std::string(SCULPT_DATA_DIR "/scenes/") + name + ".json"));
    }
    for (const Scene& scene : scenes) {
        const Scene back = parseScene(writeScene(scene), "written");
        EXPECT_EQ(back.operation, scene.operation);
        EXPECT_EQ(back.voxelSize, scene.voxelSize);
        EXPECT_EQ(back.primitives.usesGraph(), scene.primitives.usesGraph());
        ASSERT_EQ(back.primitives.primitives().size(), scene.primitives.primitives().size());
        for (std::size_t i = 0; i < back.primitives.primitives().size(); ++i) {
            const Primitive &a = scene.primitives.primitives()[i], &b = back.primitives.primitives()[i];
            EXPECT_TRUE(a.skeleton.worldFromBox.eq(b.skeleton.worldFromBox, 1e-12)) << i;
            EXPECT_EQ(a.neighbours, b.neighbours) << i;
        }
        const auto xform = voxels(scene.voxelSize.value_or(0.5));
        const FieldImage original = rasterizePrimitives(scene.primitives, *xform);
        const FieldImage written = rasterizePrimitives(back.primitives, *xform);
        const auto& list = scene.primitives.primitives();
        if (std::all_of(list.begin(), list.end(),
                        [](const Primitive& p) { return p.skeleton.worldFromBox.eq(openvdb::Mat3d::identity()); })) {
            EXPECT_EQ(gridChecksum(written.grid()), gridChecksum(original.grid()));  // bit for bit
        } else {
            EXPECT_NEAR(measureField(written).volume, measureField(original).volume, 1e-6);
        }
    }
}

TEST(Rasterizer, ReportsProgressAndStopsWhenAsked)
{
    const Scene scene = readScene(SCULPT_DATA_DIR "/scenes/snowman.json");
    test::ProgressLog log;
    const FieldImage field = rasterizePrimitives(scene.primitives, *voxels(0.25), 3.0, log.callback());
    EXPECT_GE(log.fractions().size(), 10u);
    EXPECT_TRUE(log.monotone());
    EXPECT_EQ(gridChecksum(field.grid()), gridChecksum(rasterizePrimitives(scene.primitives, *voxels(0.25)).grid()));
    test::ProgressLog stop(0);
    EXPECT_THROW(rasterizePrimitives(scene.primitives, *voxels(0.25), 3.0, stop.callback()), Cancelled);
}

}  // namespace
}  // namespace sculpt
