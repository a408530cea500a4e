// SPDX-License-Identifier: Apache-2.0
// The sculpting session (sculpt/): strokes, symmetry, undo/redo, stroke scripts and replays.

#include "core/base/errors.h"
#include "core/base/text_format.h"
#include "core/field/csg_combine.h"
#include "core/field/grid_checksum.h"
#include "core/io/mesh_file.h"
#include "core/io/vdb_file.h"
#include "core/mesh/field_measures.h"
#include "core/mesh/incremental_mesher.h"
#include "core/motion/surface_flows.h"
#include "core/primitives/analytic_shapes.h"
#include "core/scan/scan_readers.h"
#include "core/solids/hollow.h"
#include "sculpt/session/document.h"
#include "sculpt/session/import_preview.h"
#include "sculpt/session/script_replay.h"
#include "sculpt/session/sculpt_session.h"
#include "sculpt/session/shape_import.h"
#include "sculpt/session/stroke_script.h"
#include "tests/support/cgal_data.h"
#include "tests/support/temp_dir.h"

#include <gtest/gtest.h>
#include <openvdb/tools/Interpolation.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <random>

namespace sculpt {
namespace {

using openvdb::Vec3d;

Stroke strokeOf(BrushTool tool, double radius, std::vector<Vec3d> points, double strength = 0.7)
{
    Stroke stroke;
    stroke.brush.tool = tool;
    stroke.brush.radiusWorld = radius;
    stroke.brush.strength = strength;
    for (const Vec3d& p : points) stroke.samples.push_back({p, 1.0, Vec3d(0, 0, -1)});
    return stroke;
}

std::uint64_t checksumOf(const SculptSession& session) { return gridChecksum(session.field().grid()); }

std::shared_ptr<const PrimitiveStamp> blobStamp()
{
    Primitive blob;
    blob.kernel.radius = 3.0;
    return std::make_shared<const PrimitiveStamp>(
        PrimitiveStamp{PrimitiveSet({blob}, 0.5, false), CsgOperation::Union});
}

TEST(StrokeStamps, SpacedAlongThePathWithInterpolatedPressure)
{
    Stroke stroke = strokeOf(BrushTool::Add, 2.0, {Vec3d(0, 0, 0), Vec3d(4, 0, 0), Vec3d(4, 6, 0)});
    stroke.samples[0].pressure = 0.2;
    stroke.samples[2].pressure = 1.0;
    stroke.samples[1].pressure = 0.6;
    stroke.spacing = 0.25;  // 0.5 apart along a path 10 long: 21 stamps
    const std::vector<BrushStamp> stamps = strokeStamps(stroke);
    ASSERT_EQ(stamps.size(), 21u);
    EXPECT_EQ(stamps.front().centreWorld, Vec3d(0, 0, 0));
    EXPECT_EQ(stamps.back().centreWorld, Vec3d(4, 6, 0));
    EXPECT_NEAR(stamps[8].centreWorld.x(), 4.0, 1e-12);  // the corner
    EXPECT_NEAR(stamps[8].pressure, 0.6, 1e-12);
    EXPECT_NEAR(stamps[4].pressure, 0.4, 1e-12);
    for (size_t i = 1; i < stamps.size(); ++i) {
        EXPECT_NEAR((stamps[i].centreWorld - stamps[i].previousWorld).length(), 0.5, 1e-9);
        EXPECT_EQ(stamps[i].previousWorld, stamps[i - 1].centreWorld);
    }
}

TEST(StrokeStamps, MirrorImagesFollowEachStampAndChainToTheirOwn)
{
    Stroke stroke = strokeOf(BrushTool::Add, 2.0, {Vec3d(1, 2, 3), Vec3d(1, 4, 3)});
    stroke.spacing = 1.0;
    stroke.symmetry.x = stroke.symmetry.z = true;
    const std::vector<BrushStamp> stamps = strokeStamps(stroke);
    ASSERT_EQ(stamps.size(), 2u * 4u);
    EXPECT_EQ(stamps[5].centreWorld, Vec3d(-1, 4, 3));
    EXPECT_EQ(stamps[5].previousWorld, stamps[1].centreWorld);
    EXPECT_EQ(stamps[7].centreWorld, Vec3d(-1, 4, -3));
    EXPECT_EQ(stamps[7].viewDirection, Vec3d(0, 0, 1));
}

/// max |phi(x, y, z) - phi(-x, y, z)| over every voxel of the grid's leaves; also counts active
/// states that differ.
std::pair<double, int> mirrorAsymmetryX(const FieldImage& field)
{
    const auto acc = field.grid().getConstAccessor();
    double worst = 0.0;
    int states = 0;
    for (auto leaf = field.grid().tree().cbeginLeaf(); leaf; ++leaf) {
        for (auto it = leaf->cbeginValueAll(); it; ++it) {
            const openvdb::Coord m(-it.getCoord().x(), it.getCoord().y(), it.getCoord().z());
            worst = std::max(worst, double(std::abs(*it - acc.getValue(m))));
            states += it.isValueOn() != acc.isValueOn(m);
        }
    }
    return {worst, states};
}

TEST(StrokeStamps, APrefixOfTheSamplesStampsAPrefixOfTheStamps)
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> step(-1.5, 1.5);
    Stroke stroke = strokeOf(BrushTool::Add, 2.0, {Vec3d(0.0)});
    for (int i = 0; i < 60; ++i)
        stroke.samples.push_back({stroke.samples.back().positionWorld + Vec3d(step(rng), step(rng), step(rng)),
                                  0.5 + 0.008 * i, Vec3d(0, 0, -1)});
    stroke.symmetry.y = true;
    const std::vector<BrushStamp> all = strokeStamps(stroke);
    StrokeStepper live(stroke);
    std::vector<BrushStamp> sofar;
    for (const StrokeSample& sample : stroke.samples) {
        for (const BrushStamp& s : live.add(sample)) sofar.push_back(s);
        ASSERT_LE(sofar.size(), all.size());
        for (size_t k = 0; k < sofar.size(); ++k) {
            ASSERT_EQ(sofar[k].centreWorld, all[k].centreWorld);
            ASSERT_EQ(sofar[k].previousWorld, all[k].previousWorld);
            ASSERT_EQ(sofar[k].pressure, all[k].pressure);
        }
    }
    for (const BrushStamp& s : live.finish()) sofar.push_back(s);
    EXPECT_EQ(sofar.size(), all.size());
    EXPECT_EQ(all[all.size() - 2].centreWorld, stroke.samples.back().positionWorld);  // then its mirror image
}

TEST(SculptSession, ALiveStrokeEqualsTheSameStrokeAppliedWholeAndUndoesBitForBit)
{
    const Stroke stroke = strokeOf(BrushTool::Add, 3.0, {Vec3d(-6, 18, 4), Vec3d(0, 21, 6), Vec3d(8, 19, 2)});
    SculptSession whole(makeSphere(20.0, 0.5));
    SculptSession live(makeSphere(20.0, 0.5), /*liveMesh=*/true);
    const std::uint64_t before = checksumOf(live);
    whole.applyStroke(stroke);
    Stroke settings = stroke;
    settings.samples.clear();
    live.beginStroke(settings);
    std::size_t stamps = 0;
    for (const StrokeSample& sample : stroke.samples) stamps += live.extendStroke(sample).stamps;
    EXPECT_GT(stamps, 0u);  // stamped as the samples arrived, before the end
    const SculptSession::FinishedStroke done = live.endStroke();
    EXPECT_EQ(done.stroke.samples.size(), stroke.samples.size());
    EXPECT_EQ(checksumOf(live), checksumOf(whole));
    EXPECT_GT(live.remeshedBlocks(), 0u);
    ASSERT_TRUE(live.undo());
    EXPECT_EQ(checksumOf(live), before);
}

// An add stroke told to keep out of another piece (a wall placed beside the ball) builds up to it
// and not into it: no voxel of the ball is inside the wall afterwards, where the same stroke
// without it reaches in; the wall is read, never edited; undo restores the ball bit for bit.
TEST(SculptSession, AnAddStrokeStopsAtAnotherPiece)
{
    const FieldImage wall = makeBox(6.0, 0.5);  // placed at x = 14: its face at x = 8
    openvdb::Mat4d wallPlacement = openvdb::Mat4d::identity();
    wallPlacement.setTranslation(Vec3d(14.0, 0.0, 0.0));
    const std::uint64_t wallBefore = gridChecksum(wall.grid());
    const Stroke stroke = strokeOf(BrushTool::Add, 4.0, {Vec3d(5, -2, 0), Vec3d(7, 0, 0), Vec3d(9, 2, 0)}, 1.0);
    const auto voxelsInWall = [&](const SculptSession& session) {
        const auto inWall = wall.grid().getConstAccessor();
        std::size_t inside = 0;
        for (auto v = session.field().grid().cbeginValueOn(); v; ++v) {
            const Vec3d world = session.field().grid().indexToWorld(v.getCoord()) - Vec3d(14.0, 0.0, 0.0);
            inside += *v < 0.0f && openvdb::tools::BoxSampler::sample(inWall, wall.grid().worldToIndex(world)) < 0.0;
        }
        return inside;
    };
    SculptSession free(makeSphere(6.0, 0.5));
    free.applyStroke(stroke);
    EXPECT_GT(voxelsInWall(free), 50u) << "the stroke reaches into the wall's place";

    SculptSession kept(makeSphere(6.0, 0.5));
    const std::uint64_t before = checksumOf(kept);
    Stroke settings = stroke;
    settings.samples.clear();
    kept.beginStroke(settings, {KeepOut{wall, wallPlacement.inverse()}});
    for (const StrokeSample& sample : stroke.samples) kept.extendStroke(sample);
    kept.endStroke();
    EXPECT_EQ(voxelsInWall(kept), 0u);
    EXPECT_GT(measureField(kept.field()).volume, measureField(makeSphere(6.0, 0.5)).volume * 1.02) << "clay was added";
    EXPECT_EQ(gridChecksum(wall.grid()), wallBefore);
    ASSERT_TRUE(kept.undo());
    EXPECT_EQ(checksumOf(kept), before);
}

TEST(SculptSession, ACancelledLiveStrokeLeavesTheDocumentAsItWas)
{
    SculptSession session(makeSphere(20.0, 0.5), true);
    const std::uint64_t before = checksumOf(session);
    Stroke settings = strokeOf(BrushTool::Carve, 3.0, {});
    session.beginStroke(settings);
    session.extendStroke({Vec3d(0, 20, 0), 1.0, Vec3d(0, -1, 0)});
    ASSERT_NE(checksumOf(session), before);
    EXPECT_THROW(session.extendStroke({Vec3d(0, 20, 0), 2.0, Vec3d(0, -1, 0)}), InputError);  // pressure > 1
    session.cancelStroke();
    EXPECT_EQ(checksumOf(session), before);
    EXPECT_EQ(session.history().undoCount(), 0u);
}

TEST(SculptSession, StrokesWithXSymmetryKeepASymmetricModelSymmetric)
{
    const double h = 0.5;
    for (const BrushTool tool : {BrushTool::Add, BrushTool::Carve, BrushTool::Inflate, BrushTool::Smooth,
                                 BrushTool::Flatten, BrushTool::Grab, BrushTool::Pinch}) {
        SculptSession session(makeSphere(12.0, h));
        ASSERT_EQ(mirrorAsymmetryX(session.field()).first, 0.0);
        Stroke stroke = strokeOf(tool, 3.0, {Vec3d(8.0, 8.0, 4.0), Vec3d(9.0, 5.0, 6.0), Vec3d(8.0, 2.0, 8.5)});
        stroke.symmetry.x = true;
        session.applyStroke(stroke);
        const auto [worst, states] = mirrorAsymmetryX(session.field());
        EXPECT_LE(worst, 1e-5 * h) << brushToolName(tool);
        EXPECT_EQ(states, 0) << brushToolName(tool);
    }
}

TEST(SculptSession, HundredRandomStrokesUndoToTheOriginalAndRedoToTheResultBitForBit)
{
    const double R = 12.0;
    constexpr unsigned kSeed = 7;
    SculptSession session(makeSphere(R, 0.5));
    std::mt19937 random(kSeed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), radius(1.5, 4.0), strength(0.2, 1.0);
    const std::vector<BrushTool> tools{BrushTool::Add,     BrushTool::Carve,  BrushTool::Inflate,
                                       BrushTool::Deflate, BrushTool::Smooth, BrushTool::Flatten,
                                       BrushTool::Grab,    BrushTool::Pinch,  BrushTool::Primitive};
    const auto onSurface = [&] {
        Vec3d d(unit(random), unit(random), unit(random));
        return d.unit() * R;
    };
    std::vector<std::uint64_t> checksums{checksumOf(session)};  // [i]: before stroke i
    for (int i = 0; i < 100; ++i) {
        const Vec3d start = onSurface();
        Stroke stroke = strokeOf(tools[size_t(i) % tools.size()], radius(random), {start}, strength(random));
        stroke.samples.push_back({start + Vec3d(unit(random), unit(random), unit(random)) * 3.0, 0.5, Vec3d(0, 0, -1)});
        stroke.brush.falloff = Falloff(i % 4);
        stroke.brush.keepVolume = i % 3 == 0;
        stroke.symmetry.x = i % 5 == 0;
        stroke.spacing = 0.5;
        if (stroke.brush.tool == BrushTool::Primitive) stroke.brush.primitive = blobStamp();
        session.applyStroke(stroke);
        checksums.push_back(checksumOf(session));
    }
    ASSERT_NE(checksums.back(), checksums.front());
    EXPECT_EQ(session.history().undoCount(), 100u);
    const auto strokeName = [&](size_t i) {
        return "stroke " + std::to_string(i) + " (" + brushToolName(tools[i % tools.size()]) + ", seed " +
               std::to_string(kSeed) + ")";
    };
    for (size_t i = 100; i-- > 0;) {
        ASSERT_TRUE(session.undo());
        ASSERT_EQ(checksumOf(session), checksums[i]) << "undo of " << strokeName(i) << " is not bit-exact";
    }
    EXPECT_FALSE(session.undo());
    EXPECT_EQ(session.history().redoCount(), 100u);
    for (size_t i = 0; i < 100; ++i) {
        ASSERT_TRUE(session.redo());
        ASSERT_EQ(checksumOf(session), checksums[i + 1]) << "redo of " << strokeName(i) << " is not bit-exact";
    }
}

TEST(SculptSession, UndoMemoryFollowsTheTouchedLeavesNotTheModel)
{
    std::vector<std::size_t> bytes, leaves, modelLeaves;
    for (const double R : {10.0, 40.0}) {
        SculptSession session(makeSphere(R, 0.5));
        const auto report = session.applyStroke(strokeOf(BrushTool::Add, 3.0, {Vec3d(R, 0, 0), Vec3d(R, 0, 4)}));
        bytes.push_back(session.history().memoryBytes());
        leaves.push_back(report.leavesChanged);
        modelLeaves.push_back(session.field().grid().tree().leafCount());
        EXPECT_EQ(report.journalBytes, session.history().memoryBytes());
        // A saved leaf is its values (2 KiB), masks and bookkeeping; a saved tile much less.
        EXPECT_LT(double(bytes.back()) / double(leaves.back()), 2400.0);
        EXPECT_GT(double(bytes.back()) / double(leaves.back()), 1000.0);
    }
    EXPECT_GT(double(modelLeaves[1]) / double(modelLeaves[0]), 10.0);
    EXPECT_LT(double(bytes[1]) / double(bytes[0]), 1.5);
}

TEST(SculptSession, HistoryForgetsTheOldestStrokesBeyondItsBudget)
{
    const std::size_t budget = 400 * 1024;
    SculptSession session(makeSphere(12.0, 0.5), false, budget);
    std::vector<std::uint64_t> states{checksumOf(session)};
    for (int i = 0; i < 12; ++i) {
        const double a = 0.5 * i;
        session.applyStroke(strokeOf(BrushTool::Add, 2.5, {Vec3d(12 * std::cos(a), 12 * std::sin(a), 0)}));
        states.push_back(checksumOf(session));
        EXPECT_LE(session.history().memoryBytes(), budget);
    }
    const std::size_t kept = session.history().undoCount();
    EXPECT_LT(kept, 12u);
    EXPECT_EQ(session.history().droppedCount(), 12u - kept);
    std::size_t undone = 0;
    while (session.undo()) ++undone;  // undoing may forget more: redo entries can be larger
    EXPECT_GE(undone, kept - 1);
    EXPECT_EQ(checksumOf(session), states[12 - undone]);  // back to the oldest state still known
}

TEST(SculptSession, AFailedStrokeLeavesTheDocumentAsItWas)
{
    SculptSession session(makeSphere(12.0, 0.5));
    const std::uint64_t before = checksumOf(session);
    Stroke stroke = strokeOf(BrushTool::Add, 3.0, {Vec3d(12, 0, 0), Vec3d(0, 12, 0)});
    stroke.samples[1].pressure = 0.0;  // invalid
    EXPECT_THROW(session.applyStroke(stroke), InputError);
    EXPECT_THROW(session.applyStroke(strokeOf(BrushTool::Add, 500.0, {Vec3d(12, 0, 0)})), InputError);
    EXPECT_EQ(checksumOf(session), before);
    EXPECT_EQ(session.history().undoCount(), 0u);
}

TEST(SculptSession, LiveMeshFollowsEveryStrokeUndoAndRedo)
{
    SculptSession session(makeSphere(12.0, 0.5), true);
    const auto trianglesNow = [&] { return session.mesher()->weldedMesh().triangles.size(); };
    const auto fresh = [&] { return meshLevelSet(session.field()).triangles.size(); };
    session.applyStroke(strokeOf(BrushTool::Add, 3.0, {Vec3d(12, 0, 0), Vec3d(8, 8, 0)}));
    EXPECT_EQ(trianglesNow(), fresh());
    session.undo();
    EXPECT_EQ(trianglesNow(), fresh());
    session.redo();
    EXPECT_EQ(trianglesNow(), fresh());
}

std::string dataPath(const std::string& name) { return std::string(SCULPT_DATA_DIR) + "/" + name; }

/// A one-piece document of `field`, as `sculpt apply` replays into (no live mesh).
Document documentOf(FieldImage field) { return Document(std::move(field), {}, {}, PieceMeshes::None); }

std::uint64_t checksumOf(const Document& document) { return gridChecksum(document.session().field().grid()); }

template <typename Event>
const Event& as(const ScriptEvent& event)
{
    return std::get<Event>(event);
}

TEST(StrokeScript, ReplaysAreBitIdenticalTwiceAndWithOneOrTwoThreads)
{
    const StrokeScript script = readStrokeScript(dataPath("strokes/face.json"));
    std::vector<std::uint64_t> results;
    for (const int threads : {2, 1, 2}) {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
        Document document = documentOf(makeSphere(50.0, 0.5));
        const ReplayReport done = replayScript(document, script, "face.json");
        EXPECT_GT(done.strokes, 10u);
        EXPECT_EQ(done.undos, 2u);
        results.push_back(checksumOf(document));
    }
    EXPECT_EQ(results[0], results[1]);
    EXPECT_EQ(results[0], results[2]);
}

TEST(StrokeScript, KeepVolumeSmoothingOfTheSculptedFaceHoldsItsMeshVolume)
{
    Document document = documentOf(makeSphere(50.0, 0.5));
    replayScript(document, readStrokeScript(dataPath("strokes/face.json")), "face.json");
    FieldImage face = document.session().takeField();
    const double before = measureField(face).volume;
    smooth(face, 30, true);
    EXPECT_NEAR(measureField(face).volume, before, 0.001 * before) << "after 30 iterations";
    smooth(face, 170, true);
    EXPECT_NEAR(measureField(face).volume, before, 0.001 * before) << "after 200 iterations";
}

/// The error message of parsing `events` (a JSON array) as a script.
std::string parseError(const std::string& events)
{
    try {
        parseStrokeScript(R"({"format": "sculpt-strokes", "version": 1, "events": )" + events + "}", "s.json", ".");
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

TEST(StrokeScript, AWrittenScriptReadsBackAndReplaysBitForBit)
{
    StrokeScript script;
    Stroke add = strokeOf(BrushTool::Add, 2.5, {Vec3d(0.1, 20.3, 1.0 / 3.0), Vec3d(4.7, 19.1, 2.0 / 7.0)});
    add.samples[1].pressure = 0.37;
    add.symmetry.x = true;
    script.events.push_back(script::StrokeEvent{add, {}});
    Stroke smooth = strokeOf(BrushTool::Smooth, 3.0, {Vec3d(0, 20, 0)});
    smooth.brush.keepVolume = true;
    script.events.push_back(script::StrokeEvent{smooth, {}});
    script.events.push_back(script::UndoEvent{});
    const std::string scene =
        R"({"iso": 0.5, "operation": "union", "primitives": [{"kernel": "soft-object", "radius": 4, "skeleton": {"type": "point", "position": [0, 0, 0]}}]})";
    Stroke blob = strokeOf(BrushTool::Primitive, 2.0, {Vec3d(0, 0, 20)});
    const ScriptEvent parsedBlob =
        parseStrokeScript(R"({"events": [{"tool": "primitive", "radius": 2, "primitives": )" + scene +
                              R"(, "samples": [[0, 0, 20]]}]})",
                          "inline", ".")
            .events[0];
    blob.brush.primitive = as<script::StrokeEvent>(parsedBlob).stroke.brush.primitive;
    script.events.push_back(script::StrokeEvent{blob, {scene, ""}});
    // A follow stroke names its target file: the replay reads it again.
    const test::TempDir dir;
    writeFieldImage(makeBox(17.0, 0.7), dir / "box.vdb");
    Stroke follow = strokeOf(BrushTool::Follow, 5.0, {Vec3d(20, 0, 0), Vec3d(19, 5, 0)});
    follow.brush.target = std::make_shared<const FieldImage>(readFieldImage(dir / "box.vdb"));
    script.events.push_back(script::StrokeEvent{follow, {"", "box.vdb"}});

    const StrokeScript back = parseStrokeScript(writeStrokeScript(script), "written", dir.path());
    ASSERT_EQ(back.events.size(), script.events.size());
    EXPECT_EQ(as<script::StrokeEvent>(back.events[0]).stroke.samples[1].positionWorld, add.samples[1].positionWorld);
    EXPECT_EQ(as<script::StrokeEvent>(back.events[0]).stroke.samples[1].pressure, 0.37);
    EXPECT_TRUE(as<script::StrokeEvent>(back.events[0]).stroke.symmetry.x);
    EXPECT_TRUE(as<script::StrokeEvent>(back.events[1]).stroke.brush.keepVolume);
    EXPECT_TRUE(std::holds_alternative<script::UndoEvent>(back.events[2]));
    EXPECT_EQ(as<script::StrokeEvent>(back.events[4]).sources.targetPath, "box.vdb");
    Document a = documentOf(makeSphere(20.0, 0.5)), b = documentOf(makeSphere(20.0, 0.5));
    replayScript(a, script, "original");
    replayScript(b, back, "written");
    EXPECT_EQ(checksumOf(a), checksumOf(b));
}

// A mask painted by a stroke, then inverted, and a perspective cut mirrored across x: the script
// reads back to the same events, replays bit for bit (surface and mask), the cut as the core
// makes it, and each is one undo step.
TEST(StrokeScript, MaskStrokesMaskActionsAndCutsReplayBitForBit)
{
    StrokeScript script;
    script.events.push_back(
        script::StrokeEvent{strokeOf(BrushTool::Mask, 6.0, {Vec3d(20, 0, 0), Vec3d(14, 14, 0)}), {}});
    script.events.push_back(script::MaskEvent{MaskOperation::Invert, 1});
    script::CutEvent cut;
    cut.prism.viewFromWorld.setTranslation(Vec3d(0.0, 0.0, -100.0));
    cut.prism.perspective = true;
    cut.prism.polygon = {{0.05, -0.3}, {0.3, -0.3}, {0.3, 0.3}, {0.05, 0.3}};
    cut.prism.nearDepth = 70.0;
    cut.prism.mirror = {true, false, false};
    script.events.push_back(cut);
    const StrokeScript back = parseStrokeScript(writeStrokeScript(script), "written", ".");
    ASSERT_EQ(back.events.size(), 3u);
    EXPECT_EQ(as<script::MaskEvent>(back.events[1]).operation, MaskOperation::Invert);
    const ViewPrism& prism = as<script::CutEvent>(back.events[2]).prism;
    EXPECT_EQ(prism.polygon, cut.prism.polygon);
    EXPECT_EQ(prism.viewFromWorld, cut.prism.viewFromWorld);
    EXPECT_TRUE(prism.mirror[0]);
    EXPECT_FALSE(std::isfinite(prism.farDepth));

    Document a = documentOf(makeSphere(20.0, 0.5)), b = documentOf(makeSphere(20.0, 0.5));
    const std::uint64_t start = checksumOf(a);
    const ReplayReport done = replayScript(a, script, "original");
    EXPECT_EQ(done.maskOperations, 1u);
    EXPECT_EQ(done.cuts, 1u);
    replayScript(b, back, "written");
    EXPECT_EQ(checksumOf(a), checksumOf(b));
    ASSERT_NE(a.session().field().mask(), nullptr);
    EXPECT_EQ(gridChecksum(*a.session().field().mask()), gridChecksum(*b.session().field().mask()));
    // The inverted mask holds nearly everything but where the stroke painted: the cut still cuts
    // (a cut is not a brush: it ignores the mask, as a saw would).
    EXPECT_NE(checksumOf(a), start);
    const SculptSession whole(makeSphere(20.0, 0.5));
    EXPECT_EQ(checksumOf(a), gridChecksum(applyPrism(whole.field(), cut.prism, PrismMode::Cut).grid()));
    const std::uint64_t maskAfter = gridChecksum(*a.session().field().mask());
    ASSERT_TRUE(a.undo());  // the cut
    EXPECT_EQ(checksumOf(a), start);
    EXPECT_EQ(gridChecksum(*a.session().field().mask()), maskAfter);
    ASSERT_TRUE(a.undo());  // the invert
    ASSERT_TRUE(a.undo());  // the mask stroke
    EXPECT_EQ(a.session().field().mask(), nullptr);
    EXPECT_TRUE(a.undoLabels().empty());
}

TEST(StrokeScript, MaskSelectionsAndDrainHolesReplayBitForBitAndUndoAsOneStepEach)
{
    HollowOptions options;
    options.thicknessWorld = 2.0;
    const FieldImage shell = hollow(makeSphere(20.0, 0.5), options).field;  // walls at r = 18 and 20
    StrokeScript script;
    const script::DrainEvent drain{{Vec3d(21, 0, 0), Vec3d(16, 0, 0), 1.5}};
    script.events.push_back(drain);
    const auto selection = [&](MaskSelectionKind kind, bool erase, const std::function<void(MaskSelection&)>& set) {
        script::MaskSelectionEvent event;
        event.selection.kind = kind;
        event.selection.erase = erase;
        set(event.selection);
        script.events.push_back(event);
    };
    const auto frontBox = [](double x0) {
        ViewPrism prism;
        prism.viewFromWorld.setTranslation(Vec3d(0.0, 0.0, -100.0));
        prism.polygon = {{x0, -30.0}, {30.0, -30.0}, {30.0, 30.0}, {x0, 30.0}};
        return prism;
    };
    // Mask x > 5, unmask x > 10, mask every wall (all are thinner than 3), unmask the inner one
    // (a hollow of radius 18: concave), unmask the whole island: each changes the mask.
    selection(MaskSelectionKind::Prism, false, [&](MaskSelection& m) { m.prism = frontBox(5.0); });
    selection(MaskSelectionKind::Prism, true, [&](MaskSelection& m) { m.prism = frontBox(10.0); });
    selection(MaskSelectionKind::Thin, false, [](MaskSelection& m) { m.thicknessWorld = 3.0; });
    selection(MaskSelectionKind::Cavity, true, [](MaskSelection& m) { m.creaseRadiusWorld = 30.0; });
    selection(MaskSelectionKind::Island, true, [](MaskSelection& m) { m.point = Vec3d(0.0, 20.0, 0.0); });
    const StrokeScript back = parseStrokeScript(writeStrokeScript(script), "written", ".");
    ASSERT_EQ(back.events.size(), script.events.size());
    const auto selected = [&back](std::size_t i) { return as<script::MaskSelectionEvent>(back.events[i]).selection; };
    EXPECT_EQ(as<script::DrainEvent>(back.events[0]).hole.to, drain.hole.to);
    EXPECT_EQ(selected(2).prism.polygon, frontBox(10.0).polygon);
    EXPECT_TRUE(selected(2).erase);
    EXPECT_EQ(selected(3).thicknessWorld, 3.0);
    EXPECT_EQ(selected(4).creaseRadiusWorld, 30.0);
    EXPECT_EQ(selected(5).point, Vec3d(0.0, 20.0, 0.0));

    Document a = documentOf(shell.deepCopy()), b = documentOf(shell.deepCopy());
    std::vector<std::pair<std::uint64_t, std::uint64_t>> states{{checksumOf(a), 0}};
    const auto maskOf = [](const Document& d) {
        const FieldImage& field = d.session().field();
        return field.mask() ? gridChecksum(*field.mask()) : 0;
    };
    for (std::size_t i = 0; i < script.events.size(); ++i) {
        replayScript(a, StrokeScript{{script.events[i]}}, "original");
        states.emplace_back(checksumOf(a), maskOf(a));
        EXPECT_NE(states[i + 1], states[i]) << "event " << i << " changed something";
    }
    const ReplayReport done = replayScript(b, back, "written");
    EXPECT_EQ(done.drains, 1u);
    EXPECT_EQ(done.maskOperations, 5u);
    EXPECT_EQ(std::make_pair(checksumOf(b), maskOf(b)), states.back());
    for (std::size_t i = script.events.size(); i > 0; --i) {
        ASSERT_TRUE(a.undo());
        EXPECT_EQ(std::make_pair(checksumOf(a), maskOf(a)), states[i - 1]) << "undoing event " << i - 1;
    }
    EXPECT_TRUE(a.undoLabels().empty());
}

/// Three pieces apart: a body, an eye on a finer lattice, a hat above.
std::vector<Piece> threePieces()
{
    std::vector<Piece> pieces{{{"body"}, makeSphere(10.0, 0.5)},
                              {{"eye", {0.1f, 0.3f, 0.9f}}, makeSphere(3.0, 0.25)},
                              {{"hat", {0.9f, 0.2f, 0.2f}}, makeBox(4.0, 0.5)}};
    pieces[1].placement.setTranslation(Vec3d(20.0, 0.0, 0.0));
    pieces[2].placement.setTranslation(Vec3d(0.0, 25.0, 0.0));
    return pieces;
}

std::vector<Piece> copied(const std::vector<Piece>& pieces)
{
    std::vector<Piece> copies;
    for (const Piece& piece : pieces) copies.emplace_back(piece, piece.field.deepCopy());
    return copies;
}

// The pieces' edits (select, looks, a move pushing another aside, a placement applied,
// duplicate, split, merge, delete, undo and redo, a stroke on another piece), applied as the
// window lands them, are logged by the document; its log reads back and replays on the document
// as it was to every piece bit for bit.
TEST(StrokeScript, PieceEditsAreLoggedAndReplayToEveryPieceBitForBit)
{
    const std::vector<Piece> start = threePieces();
    Document a(copied(start), {}, {}, PieceMeshes::None);
    openvdb::Mat4d moved = openvdb::Mat4d::identity();
    moved.setTranslation(Vec3d(8.0, 0.0, 0.0));  // the body into the eye: the eye is pushed aside
    std::vector<PieceLook> looks;
    for (const DocumentPiece& piece : a.pieces()) looks.push_back(piece.look);
    looks[2].name = "cap";
    looks[2].visible = false;
    const std::vector<ScriptEvent> edits = {script::PieceLooksEvent{looks, "rename"},
                                            script::MovePieceEvent{0, moved, {1}},
                                            script::ApplyPlacementEvent{0},
                                            script::DuplicatePieceEvent{1},
                                            script::SplitPieceEvent{3},
                                            script::MergePiecesEvent{0, 2},
                                            script::UndoEvent{},
                                            script::RedoEvent{},
                                            script::SelectPieceEvent{1},
                                            script::StrokeEvent{strokeOf(BrushTool::Add, 1.5, {Vec3d(0, 3, 0)}), {}},
                                            script::DeletePieceEvent{2}};
    ReplayReport done;
    for (std::size_t i = 0; i < edits.size(); ++i) applyScriptEvent(a, edits[i], "edit " + std::to_string(i), done);
    EXPECT_EQ(done.pieceEdits, 8u);
    EXPECT_EQ(done.strokes, 1u);
    ASSERT_EQ(a.pieces().size(), 2u);
    EXPECT_EQ(a.pieces()[0].look.placement, openvdb::Mat4d::identity()) << "the placement was applied";

    const test::TempDir dir;
    a.saveStrokes(dir / "log.json");
    const StrokeScript log = readStrokeScript(dir / "log.json");
    Document b(copied(start), {}, {}, PieceMeshes::None);
    replayScript(b, log, "log.json");
    ASSERT_EQ(b.pieces().size(), a.pieces().size());
    for (std::size_t i = 0; i < a.pieces().size(); ++i) {
        const DocumentPiece &original = a.pieces()[i], &replayed = b.pieces()[i];
        EXPECT_EQ(gridChecksum(replayed.session->field().grid()), gridChecksum(original.session->field().grid()))
            << original.look.name;
        EXPECT_EQ(replayed.look.name, original.look.name);
        EXPECT_EQ(replayed.look.placement, original.look.placement);
        EXPECT_EQ(replayed.look.visible, original.look.visible);
    }
    EXPECT_EQ(b.activePiece(), a.activePiece());
}

TEST(StrokeScript, APieceEditNamesTheEventAndWhatIsWrong)
{
    Document document(threePieces(), {}, {}, PieceMeshes::None);
    ReplayReport done;
    try {
        applyScriptEvent(document, script::DeletePieceEvent{7}, "s.json: events[0]", done);
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "s.json: events[0] (piece edit): piece 7: the document has 3 pieces");
    }
    EXPECT_EQ(document.pieces().size(), 3u);
    EXPECT_EQ(parseError(R"([{"action": "piece", "edit": "move", "piece": 0, "placement": [0,0,0,0, 0,0,0,0, )"
                         R"(0,0,0,0, 0,0,0,1]}])"),
              "s.json: events[0]: field 'placement' cannot place a piece: it flattens the piece (no volume)");
    EXPECT_EQ(parseError(R"([{"action": "piece", "edit": "move", "piece": 0, "placement": [1,0,0,0, 0,1,0,0, )"
                         R"(0,0,1,0, 5,0,0,1], "push": [1.5]}])"),
              "s.json: events[0]: field 'push[0]' must be a whole number from 0 to 100000 (got 1.5)");
    EXPECT_EQ(parseError(R"([{"action": "piece", "edit": "select", "piece": -1}])"),
              "s.json: events[0]: field 'piece' must be a whole number from 0 to 100000 (got -1)");
    EXPECT_EQ(parseError(R"([{"action": "piece", "edit": "glue", "piece": 0}])").substr(0, 47),
              "s.json: events[0]: field 'edit' is \"glue\" (expe");
}

TEST(StrokeScript, ErrorsNameTheEventAndTheField)
{
    const std::string ok = R"("samples": [[1, 2, 3]])";
    EXPECT_EQ(parseError(R"([{"action": "undo"}, {"tool": "sponge", "radius": 1, )" + ok + "}]"),
              "s.json: events[1] ('sponge' stroke): unknown tool \"sponge\" (expected add, carve, inflate, "
              "deflate, smooth, flatten, grab, pinch, follow, primitive, mask or unmask)");
    EXPECT_EQ(parseError(R"([{"tool": "add", )" + ok + "}]"),
              "s.json: events[0] ('add' stroke): missing field 'radius'");
    EXPECT_EQ(parseError(R"([{"tool": "add", "radius": 0, )" + ok + "}]"),
              "s.json: events[0] ('add' stroke): field 'radius' must be a positive number (got 0)");
    EXPECT_EQ(parseError(R"([{"tool": "add", "radius": -2, )" + ok + "}]"),
              "s.json: events[0] ('add' stroke): field 'radius' must be a positive number (got -2)");
    EXPECT_EQ(parseError(R"([{"tool": "add", "radius": 1, "samples": [[1, 1e999, 3]]}])"),
              "s.json: malformed JSON at events[0].samples[0][1] ([json.exception.out_of_range.406] number overflow "
              "parsing '1e999')");
    EXPECT_EQ(parseError(R"([{"tool": "add", "radius": 1, "samples": [[1, "inf", 3]]}])"),
              "s.json: events[0] ('add' stroke): samples[0]: field 'position' must be an array of 3 finite numbers");
    EXPECT_EQ(parseError(R"([{"tool": "add", "radius": 1, "samples": [{"position": [1, 2, 3], "pressure": 2}]}])"),
              "s.json: events[0] ('add' stroke): field 'samples[0].pressure' must be in (0, 1] (got 2)");
    EXPECT_EQ(parseError(R"([{"tool": "add", "radius": 1, "samples": []}])"),
              "s.json: events[0] ('add' stroke): field 'samples' is empty: a stroke needs at least one");
    EXPECT_EQ(
        parseError(R"([{"action": "again"}])"),
        "s.json: events[0]: field 'action' is \"again\" (expected \"undo\", \"redo\", \"mask\", \"cut\", \"drain\" or "
        "\"piece\")");
    EXPECT_EQ(parseError(R"([{"tool": "primitive", "radius": 1, "primitives": "missing.json", )" + ok + "}]"),
              "s.json: events[0] ('primitive' stroke): field 'primitives': ./missing.json: cannot read the scene file");
    EXPECT_EQ(parseError(R"([{"tool": "follow", "radius": 1, )" + ok + "}]"),
              "s.json: events[0] ('follow' stroke): missing field 'target'");
    EXPECT_EQ(parseError(R"([{"tool": "follow", "radius": 1, "target": "missing.vdb", )" + ok + "}]").substr(0, 84),
              "s.json: events[0] ('follow' stroke): field 'target': ./missing.vdb: no such file");
    EXPECT_NE(parseError("[{").find("malformed JSON"), std::string::npos);
    EXPECT_EQ(parseError(R"([{"tool": "add", "radius": 1, "strenght": 1, )" + ok + "}]").substr(0, 68),
              "s.json: events[0] ('add' stroke): unknown field 'strenght' (expected");
    EXPECT_NE(parseError(R"([{"tool": "add", "radius": 1, "symmetry": ["w"], )" + ok + "}]").find("'symmetry'"),
              std::string::npos);
}

TEST(StrokeScript, ReplayNamesTheEventThatCannotBeApplied)
{
    Document session = documentOf(makeSphere(10.0, 0.5));
    const auto script = parseStrokeScript(
        R"({"events": [{"tool": "add", "radius": 1, "samples": [[10, 0, 0]]}, {"action": "undo"}, {"action": "undo"}]})",
        "s.json", ".");
    try {
        replayScript(session, script, "s.json");
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "s.json: events[2]: undo with nothing to undo");
    }
    const auto huge =
        parseStrokeScript(R"({"events": [{"tool": "add", "radius": 300, "samples": [[10, 0, 0]]}]})", "s.json", ".");
    try {
        replayScript(session, huge, "s.json");
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(
                      "s.json: events[0] ('add' stroke): field 'radius' (300) is larger than the model"),
                  std::string::npos)
            << e.what();
    }
}

TEST(StrokeScript, StrokesOfAMillionSamplesOrTooManyStampsAreRefusedBeforeAnyStamp)
{
    std::string samples;
    for (int i = 0; i < 1000000; ++i) samples += (i ? ",[" : "[") + std::to_string(i % 7) + ",0,0]";
    const auto start = std::chrono::steady_clock::now();
    const std::string many = parseError(R"([{"tool": "add", "radius": 1, "samples": [)" + samples + "]}]");
    EXPECT_EQ(many, "s.json: events[0] ('add' stroke): field 'samples' holds 1000000 samples, more than a stroke may "
                    "(100000): split it into several strokes");
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(20));
    // Two samples 20 apart at a spacing of 0.01 x 0.01 radii: 200,000 stamps.
    const std::string far =
        parseError(R"([{"tool": "add", "radius": 0.01, "spacing": 0.01, "samples": [[0, 0, 0], [20, 0, 0]]}])");
    EXPECT_NE(far.find("the stroke would make 200002 stamps, more than 100000"), std::string::npos) << far;
}

}  // namespace
}  // namespace sculpt

namespace sculpt {
namespace {

const char* kMri = "/usr/share/mricron/templates/ch2bet.nii.gz";

TEST(ImportPreview, AScanPreviewIsTheImportCoarselyAndFollowsTheIsoValue)
{
    if (!std::filesystem::exists(kMri)) GTEST_SKIP() << kMri << " missing: apt-get install mricron-data";
    ImportPreview preview(kMri);
    ASSERT_TRUE(preview.isScan());
    const openvdb::Coord d = preview.scan().dims();
    EXPECT_EQ(preview.defaultVoxelSize(), 1.0);
    EXPECT_NEAR(preview.previewVoxelSize(), (std::max({d.x(), d.y(), d.z()}) - 1) / 96.0, 1e-9);
    ImportOptions options;
    options.largestComponent = true;
    const std::vector<double>& histogram = preview.histogram(options);
    double samples = 0.0;
    for (double count : histogram) samples += count;
    EXPECT_EQ(samples, double(d.x()) * d.y() * d.z());
    ImportReport report;
    const FieldImage full = importShape(kMri, options, report);
    EXPECT_EQ(preview.otsuThreshold(options), report.iso);  // what the import chose
    const double fullVolume = measureField(full).volume;
    const FieldImage coarse = preview.surface(options);
    EXPECT_DOUBLE_EQ(coarse.voxelSize(), preview.previewVoxelSize());
    EXPECT_NEAR(measureField(coarse).volume, fullVolume, 0.03 * fullVolume);
    // A higher iso-value keeps less of the brain; the preview follows.
    options.iso = report.iso + 0.5 * (preview.range(options).second - report.iso);
    EXPECT_LT(measureField(preview.surface(options)).volume, 0.9 * fullVolume);
    // A crop halves the scan along x: its histogram, range and surface are the crop's.
    options.crop = openvdb::CoordBBox(openvdb::Coord(0), openvdb::Coord(d.x() / 2, d.y() - 1, d.z() - 1));
    options.iso.reset();
    double cropped = 0.0;
    for (double count : preview.histogram(options)) cropped += count;
    EXPECT_EQ(cropped, double(d.x() / 2 + 1) * d.y() * d.z());
    EXPECT_LT(measureField(preview.surface(options)).volume, 0.6 * fullVolume);
}

TEST(ImportPreview, AnOpenMeshIsReportedAndPreviewedCoarsely)
{
    // A cube of side 20 without its top face: 4 open edges.
    const test::TempDir dir;
    {
        std::ofstream off(dir / "open.off");
        off << "OFF\n8 5 0\n";
        for (int i = 0; i < 8; ++i)
            off << (i & 1 ? 10 : -10) << " " << (i & 2 ? 10 : -10) << " " << (i & 4 ? 10 : -10) << "\n";
        off << "4 0 2 3 1\n4 0 1 5 4\n4 2 6 7 3\n4 0 4 6 2\n4 1 3 7 5\n";
    }
    ImportPreview preview(dir / "open.off");
    ASSERT_FALSE(preview.isScan());
    EXPECT_FALSE(preview.meshReport().closed());
    EXPECT_EQ(preview.meshReport().boundaryEdges, 4u);
    EXPECT_NEAR(preview.defaultVoxelSize(), 20.0 / 256.0, 1e-9);
    EXPECT_NEAR(preview.previewVoxelSize(), 20.0 / 96.0, 1e-9);
    const FieldImage coarse = preview.surface({});
    EXPECT_DOUBLE_EQ(coarse.voxelSize(), preview.previewVoxelSize());
    // The surface shows where the walls are (inside is only guessed for an open mesh).
    const openvdb::CoordBBox box = coarse.grid().evalActiveVoxelBoundingBox();
    const openvdb::Vec3d lo = coarse.grid().transform().indexToWorld(box.min());
    const openvdb::Vec3d hi = coarse.grid().transform().indexToWorld(box.max());
    for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR(lo[a], -10.0, 4 * coarse.voxelSize());
        EXPECT_NEAR(hi[a], 10.0, 4 * coarse.voxelSize());
    }
}

TEST(ImportPreview, RefusesWhatTheImportRefusesNamingTheFile)
{
    const test::TempDir dir;
    std::ofstream(dir / "empty.nii") << "not a scan";
    try {
        ImportPreview preview(dir / "empty.nii");
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("empty.nii"), std::string::npos) << e.what();
    }
}

/// Two balls of radius 10, `gap` apart along x, as one closed mesh (Euler characteristic 4).
TriangleMesh twoBalls(double gap)
{
    TriangleMesh one = meshLevelSet(makeSphere(10.0, 0.1)), two;
    for (int copy = 0; copy < 2; ++copy) {
        const auto offset = std::uint32_t(two.positions.size());
        for (auto p : one.positions) {
            p[0] += float(copy * (20.0 + gap));
            two.positions.push_back(p);
        }
        for (auto t : one.triangles) two.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    }
    return two;
}

// Parts closer than about two voxels merge: the import warns, names the change and a voxel size
// that keeps the topology, and that size does.
TEST(ShapeImport, AClosedMeshWhoseTopologyTheVoxelSizeChangesGetsAWarningAndASizeThatKeepsIt)
{
    const test::TempDir dir;
    writeMesh(twoBalls(0.2), dir / "pair.ply");  // default voxel size 0.157: the gap is 1.3 voxels
    ImportReport report;
    const FieldImage merged = importShape(dir / "pair.ply", {}, report);
    EXPECT_EQ(measureField(merged).components, 1);
    ASSERT_EQ(report.warnings.size(), 1u);
    EXPECT_NE(report.warnings[0].find("Euler characteristic 4 becomes 2"), std::string::npos) << report.warnings[0];
    ASSERT_TRUE(report.topologyKeepingVoxelSize);
    EXPECT_NE(report.warnings[0].find(formatNumber(*report.topologyKeepingVoxelSize)), std::string::npos);

    ImportOptions finer;
    finer.voxelSize = report.topologyKeepingVoxelSize;
    ImportReport kept;
    const FieldImage apart = importShape(dir / "pair.ply", finer, kept);
    EXPECT_TRUE(kept.warnings.empty()) << kept.warnings.front();
    EXPECT_EQ(measureField(apart).eulerCharacteristic, 4);
    EXPECT_EQ(measureField(apart).components, 2);

    // A mesh the default voxel size resolves imports without a warning.
    ImportReport ball;
    writeMesh(meshLevelSet(makeSphere(10.0, 0.5)), dir / "ball.ply");
    importShape(dir / "ball.ply", {}, ball);
    EXPECT_TRUE(ball.warnings.empty()) << ball.warnings.front();

    // CGAL's cow (genus 0): thin legs and ears merge at the default voxel size.
    const auto cow = test::cgalMesh("cow.off");
    if (cow.empty()) GTEST_SKIP() << "CGAL's meshes missing: apt-get install libcgal-demo";
    ImportReport cowReport;
    importShape(cow, {}, cowReport);
    ASSERT_FALSE(cowReport.warnings.empty());
    EXPECT_NE(cowReport.warnings[0].find("Euler characteristic 2 becomes"), std::string::npos) << cowReport.warnings[0];
}

/// A MetaImage of bytes (header and samples in one file), `sample(i, j, k)` at spacing 0.5.
void writeByteScan(const std::filesystem::path& path, int n, const std::function<int(int, int, int)>& sample)
{
    std::ofstream file(path, std::ios::binary);
    file << "ObjectType = Image\nNDims = 3\nDimSize = " << n << " " << n << " " << n
         << "\nElementType = MET_UCHAR\nElementSpacing = 0.5 0.5 0.5\nElementDataFile = LOCAL\n";
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) file.put(char(sample(i, j, k)));
}

// A label map of three structures: a ball (1) touching a box (2) that holds a smaller ball (3)
// in a cavity. Each label imports as its own anti-aliased surface with its analytic volume and
// topology; a label the map lacks, or a label of a scan of intensities, is refused naming the file.
// A label of 2 x 2 x 2 samples is a speck at the native voxel size: the debris removal must not
// empty its piece (it did, for every piece of a 2,000-label map).
TEST(ShapeImport, ALabelNoBiggerThanASpeckIsKeptAndSaysSo)
{
    const test::TempDir dir;
    writeByteScan(dir / "labels.mha", 24, [](int i, int j, int k) {
        if (i >= 4 && i < 6 && j >= 4 && j < 6 && k >= 4 && k < 6) return 1;
        return std::hypot(i - 15.2, j - 14.9, k - 15.1) < 6.0 ? 2 : 0;
    });
    ImportReport report;
    const std::vector<Piece> pieces = importLabelPieces(dir / "labels.mha", {}, report);
    ASSERT_EQ(pieces.size(), 2u);
    const double h = pieces[0].field.voxelSize();
    const FieldMeasures speck = measureField(pieces[0].field);
    EXPECT_EQ(speck.components, 1);
    EXPECT_GT(speck.volume, 2.0 * h * h * h) << "about the 8 samples' volume, not nothing";
    EXPECT_LT(speck.volume, 16.0 * h * h * h);
    const std::string all = [&] {
        std::string text;
        for (const std::string& w : report.warnings) text += w + "\n";
        return text;
    }();
    EXPECT_NE(all.find("piece 'label 1': the shape is no bigger than a speck"), std::string::npos) << all;
    EXPECT_EQ(all.find("piece 'label 2': the shape is no bigger"), std::string::npos) << all;
}

TEST(ShapeImport, ALabelMapImportsEachLabelAsItsOwnSurface)
{
    const test::TempDir dir;
    // Off the sample lattice, so each shape holds the samples its volume says; the box's faces
    // lie halfway between samples, where the mask's surface is.
    const openvdb::Vec3d ballCentre(9.1, 16.2, 15.9), innerCentre(21.15, 16.1, 15.95);
    const double ball = 7.0, inner = 3.5, boxFrom = 14.25, boxTo = 28.25, boxHalf = 8.25;  // y and z: 16 +- 8.25
    writeByteScan(dir / "labels.mha", 64, [&](int i, int j, int k) {
        const openvdb::Vec3d p(0.5 * i, 0.5 * j, 0.5 * k);
        if ((p - innerCentre).length() < inner) return 3;
        if (p.x() > boxFrom && p.x() < boxTo && std::abs(p.y() - 16.0) < boxHalf && std::abs(p.z() - 16.0) < boxHalf)
            return 2;
        return (p - ballCentre).length() < ball ? 1 : 0;
    });
    const double cap = ballCentre.x() + ball - boxFrom;  // the height of the ball's part the box takes
    const double innerVolume = 4.0 / 3.0 * M_PI * std::pow(inner, 3);
    const std::map<int, std::pair<double, int>> expected{
        // label: volume, Euler characteristic
        {1, {4.0 / 3.0 * M_PI * std::pow(ball, 3) - M_PI * cap * cap * (3.0 * ball - cap) / 3.0, 2}},
        {2, {(boxTo - boxFrom) * 4.0 * boxHalf * boxHalf - innerVolume, 4}},  // its cavity is a second shell
        {3, {innerVolume, 2}}};
    for (const auto& [label, want] : expected) {
        ImportOptions options;
        options.label = label;
        ImportReport report;
        const FieldImage field = importShape(dir / "labels.mha", options, report);
        EXPECT_TRUE(report.maskAntiAliased) << "label " << label;
        const FieldMeasures m = measureField(field);
        EXPECT_NEAR(m.volume, want.first, 0.02 * want.first) << "label " << label;
        EXPECT_EQ(m.eulerCharacteristic, want.second) << "label " << label;
    }
    // The window's preview offers the labels and shows one.
    ImportPreview preview(dir / "labels.mha");
    EXPECT_EQ(preview.labels(), (std::vector<int>{0, 1, 2, 3}));
    ImportOptions inner3;
    inner3.label = 3;
    EXPECT_EQ(measureField(preview.surface(inner3)).components, 1);
    EXPECT_EQ(measureField(preview.surface(ImportOptions{})).components, 1) << "at Otsu's threshold: one solid";
    ImportOptions missing;
    missing.label = 4;
    ImportReport unused;
    try {
        importShape(dir / "labels.mha", missing, unused);
        ADD_FAILURE() << "label 4 imported";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("labels.mha: no sample has label 4; its labels are 0, 1, 2, 3 (4 labels)"),
                  std::string::npos)
            << e.what();
    }
    writeMesh(meshLevelSet(makeSphere(4.0, 0.5)), dir / "ball.ply");
    EXPECT_THROW(importShape(dir / "ball.ply", missing, unused), InputError) << "a label of a mesh";
}

// A label map another program wrote: FSL's JHU white-matter atlas (mricron-data, 1 mm, 48 labels).
// The genu of the corpus callosum (label 3) imports as one closed surface holding its samples.
TEST(ShapeImport, ARealAtlasLabelImportsAsTheVolumeOfItsSamples)
{
    const std::filesystem::path atlas = "/usr/share/mricron/templates/JHU-WhiteMatter-labels-1mm.nii.gz";
    if (!std::filesystem::exists(atlas)) GTEST_SKIP() << "mricron-data missing";
    const ScanVolume scan = readScan(atlas);
    const std::vector<int> labels = scan.labels();
    ASSERT_EQ(labels.size(), 49u);
    EXPECT_EQ(labels.front(), 0);
    EXPECT_EQ(labels.back(), 48);
    EXPECT_TRUE(scan.labelMask(3).twoValued());
    std::vector<float> slice(std::size_t(scan.dims().x()) * std::size_t(scan.dims().y()));
    double samples = 0.0;
    const ScanVolume genu = scan.labelMask(3);
    for (int k = 0; k < scan.dims().z(); ++k) {
        genu.readSlice(k, slice.data());
        for (const float v : slice) samples += v;
    }
    ImportOptions options;
    options.label = 3;
    ImportReport report;
    const FieldMeasures m = measureField(importShape(atlas, options, report));
    EXPECT_NEAR(m.volume, samples, 0.03 * samples) << "1 mm^3 a sample";
    EXPECT_EQ(m.components, 1);
}

}  // namespace
}  // namespace sculpt

namespace sculpt {
namespace {

/// A label map of three structures, nested and touching, as raw bytes of 0.5 mm samples: a box
/// (label 1, half side 10) holding a ball (label 2, radius 5), and a ball (label 3, radius 6)
/// touching the box's +x side. Returns each label's sample count.
std::map<int, std::size_t> writeThreeLabels(const std::filesystem::path& path, ImportOptions& options)
{
    const openvdb::Coord dims(73, 49, 49);
    const double h = 0.5;
    std::string bytes;
    std::map<int, std::size_t> counts;
    for (int k = 0; k < dims.z(); ++k)
        for (int j = 0; j < dims.y(); ++j)
            for (int i = 0; i < dims.x(); ++i) {
                const openvdb::Vec3d p(-12.0 + i * h, -12.0 + j * h, -12.0 + k * h);
                int label = std::max({std::abs(p.x()), std::abs(p.y()), std::abs(p.z())}) <= 10.0 ? 1 : 0;
                if (p.length() <= 5.0) label = 2;
                if ((p - openvdb::Vec3d(16.0, 0.0, 0.0)).length() <= 6.0) label = 3;
                bytes.push_back(char(label));
                ++counts[label];
            }
    std::ofstream(path, std::ios::binary) << bytes;
    RawLayout raw;
    raw.dims = dims;
    raw.spacing = openvdb::Vec3d(h);
    options.raw = raw;
    return counts;
}

}  // namespace

// Each label becomes a piece whose volume is its samples' (within 1%), with the shells it has
// (the box: its outside and the ball's cavity), equal to the label imported alone from the
// whole map although only the samples around it were read.
TEST(LabelImport, APiecePerLabelWithItsSamplesVolume)
{
    test::TempDir dir;
    ImportOptions options;
    const std::map<int, std::size_t> counts = writeThreeLabels(dir / "map.raw", options);
    ImportReport report;
    const std::vector<Piece> pieces = importLabelPieces(dir / "map.raw", options, report);
    ASSERT_EQ(pieces.size(), 3u);
    EXPECT_TRUE(report.maskAntiAliased);
    for (int label = 1; label <= 3; ++label) {
        const Piece& piece = pieces[std::size_t(label - 1)];
        EXPECT_EQ(piece.name, "label " + std::to_string(label));
        const FieldMeasures m = measureField(piece.field);
        const double samples = double(counts.at(label)) * 0.125;
        EXPECT_NEAR(m.volume, samples, 0.01 * samples) << piece.name;
        EXPECT_EQ(m.components, label == 1 ? 2 : 1) << piece.name;
        ImportOptions alone = options;
        alone.label = label;
        ImportReport aloneReport;
        const FieldImage whole = importShape(dir / "map.raw", alone, aloneReport);
        EXPECT_NEAR(measureField(whole).volume, m.volume, 1e-6 * m.volume) << piece.name;
    }
    EXPECT_NE(pieces[0].colour, pieces[1].colour);
}

// 3D Slicer's segmentation (.seg.nrrd) names and colours its segments in its header; a segment
// without a LabelValue (Slicer before 4.11) is its index plus one.
TEST(LabelImport, SlicerSegmentNamesAndColoursFromTheHeader)
{
    test::TempDir dir;
    ImportOptions raw;
    writeThreeLabels(dir / "map.raw", raw);
    std::ifstream in(dir / "map.raw", std::ios::binary);
    const std::string samples((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(dir / "map.seg.nrrd", std::ios::binary)
        << "NRRD0004\ntype: unsigned char\ndimension: 3\nspace: left-posterior-superior\nsizes: 73 49 49\n"
           "space directions: (0.5,0,0) (0,0.5,0) (0,0,0.5)\nkinds: domain domain domain\nencoding: raw\n"
           "space origin: (0,0,0)\n"
           "Segment0_Color:=0.9 0.3 0.2\nSegment0_ID:=Segment_1\nSegment0_LabelValue:=1\nSegment0_Name:=Liver\n"
           "Segment1_Name:=Tumour\n"
           "Segment2_Color:=0.2 0.4 0.9\nSegment2_LabelValue:=3\nSegment2_Name:=Portal vein\n\n"
        << samples;
    ImportReport report;
    const std::vector<Piece> pieces = importLabelPieces(dir / "map.seg.nrrd", ImportOptions{}, report);
    ASSERT_EQ(pieces.size(), 3u);
    EXPECT_EQ(pieces[0].name, "Liver");
    EXPECT_EQ(pieces[1].name, "Tumour");
    EXPECT_EQ(pieces[2].name, "Portal vein");
    EXPECT_EQ(pieces[0].colour, openvdb::Vec3f(0.9f, 0.3f, 0.2f));
    EXPECT_EQ(pieces[2].colour, openvdb::Vec3f(0.2f, 0.4f, 0.9f));
}

// CGAL's liver segmentation (INRIMAGE-4, gzipped; liver, vessels, a lesion) imports as a piece per
// label, each of its samples' volume within 1% (a label of a few samples, within a few of them).
TEST(LabelImport, CgalsLiverSegmentationAPiecePerLabel)
{
    const std::filesystem::path liver = test::cgalData("images/liver.inr.gz");
    if (liver.empty()) GTEST_SKIP() << "apt-get install libcgal-demo";
    const ScanVolume scan = readScan(liver);
    const double sampleVolume = scan.spacing(0) * scan.spacing(1) * scan.spacing(2);
    std::map<int, std::size_t> counts;
    for (const auto& [label, extent] : scan.labelExtents())
        if (label != kBackgroundLabel) counts[label] = extent.samples;
    ImportReport report;
    const std::vector<Piece> pieces = importLabelPieces(liver, ImportOptions{}, report);
    ASSERT_EQ(pieces.size(), counts.size());
    auto count = counts.begin();
    for (const Piece& piece : pieces) {
        EXPECT_EQ(piece.name, "label " + std::to_string(count->first));
        const double expected = double(count->second) * sampleVolume, volume = measureField(piece.field).volume;
        const double tolerance = std::max(0.01 * expected, 3.0 * sampleVolume);
        EXPECT_NEAR(volume, expected, tolerance) << piece.name;
        ++count;
    }
}

// MRIcron's atlases name their labels in a .txt and colour them in a .lut beside the volume;
// an MRI is not a label map, even of few values, and is refused in one line.
TEST(LabelImport, NamesAndColoursFromTheAtlasFilesAndRefusesIntensities)
{
    const std::filesystem::path templates = "/usr/share/mricron/templates";
    if (!std::filesystem::exists(templates / "JHU-WhiteMatter-labels-2mm.nii.gz"))
        GTEST_SKIP() << "apt-get install mricron-data";
    ImportReport report;
    const std::vector<Piece> pieces =
        importLabelPieces(templates / "JHU-WhiteMatter-labels-2mm.nii.gz", ImportOptions{}, report);
    ASSERT_EQ(pieces.size(), 48u);
    EXPECT_EQ(pieces[2].name, "Genu_of_corpus_callosum");
    EXPECT_EQ(pieces[47].name, "Tapetum_L");
    // The .lut's third entry, 203 149 149 of 255.
    EXPECT_NEAR(pieces[2].colour[0], 203.0 / 255.0, 1e-6);
    EXPECT_NEAR(pieces[2].colour[1], 149.0 / 255.0, 1e-6);
    for (const Piece& piece : pieces) EXPECT_GT(measureField(piece.field).volume, 0.0) << piece.name;
    try {
        importLabelPieces(templates / "ch2better.nii.gz", ImportOptions{}, report);
        FAIL() << "an MRI imported as labels";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("ch2better.nii.gz: its samples look like intensities"), std::string::npos) << what;
    }
}

}  // namespace sculpt
