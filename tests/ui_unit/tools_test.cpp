// SPDX-License-Identifier: Apache-2.0
// The window's tools driven by input events in a headless SculptApp (no display): a brush stroke
// and its undo, a lasso cut, a box mask, a piece moved into another (stopping at contact, then
// pushing it aside); each grid checked against `sculpt apply` of the window's stroke log or the
// properties the Xvfb replays assert.

#include "core/field/grid_checksum.h"
#include "core/io/vdb_file.h"
#include "core/primitives/analytic_shapes.h"
#include "tests/support/grid_builders.h"
#include "tests/support/run_sculpt.h"
#include "tests/ui_unit/headless_app.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sculpt::test {
namespace {

namespace fs = std::filesystem;

/// A clay ball document (sculpt new) in `dir`, and the options opening it with a stroke log.
ui::AppOptions ballWithLog(const TempDir& dir)
{
    EXPECT_EQ(runSculpt("new -o ball.vdb", dir.path().string()).exitCode, 0);
    ui::AppOptions options = headlessOptions(dir, (dir / "ball.vdb").string());
    options.strokeLog = dir / "strokes.json";
    return options;
}

/// `sculpt apply` of the window's stroke log on the ball: the field it writes.
FieldImage applied(const TempDir& dir)
{
    const CommandResult apply = runSculpt("apply ball.vdb strokes.json -o applied.vdb", dir.path().string());
    EXPECT_EQ(apply.exitCode, 0) << apply.err;
    return readFieldImage(dir / "applied.vdb");
}

TEST(HeadlessTools, ABrushStrokeUndoesBitForBitAndItsLogReplaysToTheSameGrid)
{
    TempDir dir;
    const fs::path r = dir / "r.jsonl";
    UiEvents events;
    events.untilJobEnds().move(560, 380).report(r, "before");
    events.drag(560, 380, 720, 400).report(r, "added");
    events.key("Z", {"ctrl"}).report(r, "undone").key("Z", {"ctrl", "shift"}).report(r, "redone");
    ASSERT_EQ(playHeadless(dir, events, ballWithLog(dir)), 0);
    const Reports reports(r);
    EXPECT_EQ(reports["before"]["tool_chosen"], "sculpt");
    EXPECT_GT(reports["added"]["volume"].get<double>(), reports["before"]["volume"].get<double>() + 100.0);
    EXPECT_GT(reports["added"]["stamps"].get<int>(), 3);
    EXPECT_EQ(reports["added"]["undo"], 1);
    EXPECT_EQ(reports["undone"]["checksum"], reports["before"]["checksum"]);
    EXPECT_EQ(reports["redone"]["checksum"], reports["added"]["checksum"]);
    EXPECT_EQ(formatChecksum(gridChecksum(applied(dir).grid())), reports["redone"]["checksum"]);
}

TEST(HeadlessTools, ALassoCutLandsAsOneUndoStepAndItsLogReplaysToTheSameGrid)
{
    TempDir dir;
    const fs::path r = dir / "r.jsonl";
    UiEvents events;
    const double cx = kCentreX + 250, cy = kCentreY;  // an ellipse over the ball's right edge
    events.untilJobEnds().report(r, "start").key("J").move(cx + 200, cy).press().report(r, "drawing");
    events.ellipse(cx, cy, 200, 140).release().untilJobEnds().report(r, "cut");
    events.key("Z", {"ctrl"}).report(r, "undone").key("Z", {"ctrl", "shift"}).report(r, "redone");
    ASSERT_EQ(playHeadless(dir, events, ballWithLog(dir)), 0);
    const Reports reports(r);
    EXPECT_EQ(reports["drawing"]["tool_chosen"], "gesture");
    EXPECT_TRUE(reports["drawing"]["gesture"]["drawing"].get<bool>());
    EXPECT_EQ(reports["cut"]["gesture"]["shape"], "lasso");
    const double start = reports["start"]["volume"];
    EXPECT_LT(reports["cut"]["volume"].get<double>(), 0.9 * start);
    EXPECT_GT(reports["cut"]["volume"].get<double>(), 0.5 * start);
    EXPECT_EQ(reports["cut"]["undo"], 1);
    EXPECT_EQ(reports["cut"]["notice"], "cut done (Ctrl+Z undoes it)");
    EXPECT_EQ(reports["undone"]["checksum"], reports["start"]["checksum"]);
    EXPECT_EQ(reports["redone"]["checksum"], reports["cut"]["checksum"]);
    EXPECT_EQ(formatChecksum(gridChecksum(applied(dir).grid())), reports["redone"]["checksum"]);
}

TEST(HeadlessTools, ABoxMaskMasksWithoutMovingClayAndItsLogReplaysToTheSameMask)
{
    TempDir dir;
    const fs::path r = dir / "r.jsonl";
    UiEvents events;
    // From right of the Brush panel (x < 244): a press over a panel is the panel's.
    events.untilJobEnds().report(r, "start").key("B", {"shift"});
    events.drag(kCentreX - 380, kCentreY - 300, kCentreX - 120, kCentreY + 300).untilJobEnds().report(r, "masked");
    events.key("Z", {"ctrl"}).report(r, "undone").key("Z", {"ctrl", "shift"}).report(r, "redone");
    events.move(kCentreX + 100, kCentreY - 100).press().move(kCentreX + 200, kCentreY + 100).key("Escape");
    events.release().untilJobEnds().report(r, "dropped");  // Esc while drawing: nothing is masked
    ASSERT_EQ(playHeadless(dir, events, ballWithLog(dir)), 0);
    const Reports reports(r);
    EXPECT_EQ(reports["dropped"]["undo"], reports["redone"]["undo"]);
    EXPECT_EQ(reports["dropped"]["mask_checksum"], reports["redone"]["mask_checksum"]);
    EXPECT_EQ(reports["dropped"]["notice"], "mask dropped");
    EXPECT_EQ(reports["masked"]["gesture"]["masks"], true);
    EXPECT_EQ(reports["masked"]["undo"], 1);
    EXPECT_NE(reports["masked"]["mask_checksum"], "");
    EXPECT_EQ(reports["masked"]["checksum"], reports["start"]["checksum"]) << "a mask moves no clay";
    EXPECT_EQ(reports["undone"]["mask_checksum"], reports["start"]["mask_checksum"]);
    EXPECT_EQ(reports["redone"]["mask_checksum"], reports["masked"]["mask_checksum"]);
    const FieldImage replayed = applied(dir);
    ASSERT_NE(replayed.mask(), nullptr);
    EXPECT_EQ(formatChecksum(gridChecksum(*replayed.mask())), reports["redone"]["mask_checksum"]);
}

TEST(HeadlessTools, APieceMovedIntoAnotherStopsAtContactAndAPushIsOneUndoStep)
{
    TempDir dir;
    writeVdbPieces(bodyAndBallApart(), dir / "two.vdb");  // body to x = 10, ball from 24
    const fs::path r = dir / "r.jsonl";
    UiEvents events;
    events.untilJobEnds().report(r, "opened").key("G").report(r, "grab").key("Tab").report(r, "pieces");
    events.key("G").key("X").key("2").key("0").report(r, "moving").key("Enter").report(r, "stopped");
    events.key("P").key("G").key("X").key("2").key("Enter").untilJobEnds().report(r, "pushed");
    events.key("Z", {"ctrl"}).report(r, "undone").key("Tab").report(r, "back");
    ASSERT_EQ(playHeadless(dir, events, headlessOptions(dir, (dir / "two.vdb").string())), 0);
    const Reports reports(r);
    EXPECT_EQ(reports["grab"]["tool"], "grab") << "outside pieces mode G is the grab brush";
    EXPECT_EQ(reports["pieces"]["tool_chosen"], "pieces");
    EXPECT_TRUE(reports["moving"]["pieces_tool"]["moving"].get<bool>());
    EXPECT_NE(reports["moving"]["notice"].get<std::string>().find("stopped at contact"), std::string::npos);
    const auto piece = [&reports](const std::string& name, int i) { return reports[name]["pieces"][i]; };
    // Stopped where the body's surface (x = 10 + t) meets the ball's (x = 24): within half a voxel.
    const double stopped = placedX(piece("stopped", 0));
    EXPECT_GT(stopped, 14.0 - 0.25);
    EXPECT_LE(stopped, 14.0 + 0.01);
    EXPECT_EQ(piece("stopped", 0)["checksum"], piece("opened", 0)["checksum"]) << "a move changes no voxel";
    EXPECT_TRUE(reports["pushed"]["pieces_tool"]["push"].get<bool>());
    EXPECT_NEAR(placedX(piece("pushed", 0)), stopped + 2.0, 1e-9);
    EXPECT_NE(piece("pushed", 1)["checksum"], piece("opened", 1)["checksum"]) << "the ball was dented";
    EXPECT_EQ(reports["pushed"]["undo"].get<int>(), reports["stopped"]["undo"].get<int>() + 1);
    EXPECT_EQ(piece("undone", 1)["checksum"], piece("opened", 1)["checksum"]) << "one undo: the dent...";
    EXPECT_EQ(placedX(piece("undone", 0)), stopped) << "... and the move";
    EXPECT_EQ(reports["back"]["tool_chosen"], "sculpt") << "Tab again: the tool chosen before";
}

// A placement no document may hold (scaled to a hundredth twice: 1/10,000) is dropped and says
// why; the scale before it stays.
TEST(HeadlessTools, AScaleBeyondThePlacementLimitsIsDroppedAndSaysWhy)
{
    TempDir dir;
    writeVdbPieces(bodyAndBallApart(), dir / "two.vdb");
    const fs::path r = dir / "r.jsonl";
    UiEvents events;
    events.untilJobEnds().report(r, "opened").key("Tab");
    events.key("S").key("Period").key("0").key("1").key("Enter").report(r, "once");
    events.key("S").key("Period").key("0").key("1").key("Enter").report(r, "twice");
    ASSERT_EQ(playHeadless(dir, events, headlessOptions(dir, (dir / "two.vdb").string())), 0);
    const Reports reports(r);
    EXPECT_NE(reports["once"]["pieces"][0]["placement"], reports["opened"]["pieces"][0]["placement"]);
    EXPECT_EQ(reports["once"]["undo"].get<int>(), reports["opened"]["undo"].get<int>() + 1);
    EXPECT_NE(reports["twice"]["notice"].get<std::string>().find("dropped: it scales the piece by 0.0001"),
              std::string::npos)
        << reports["twice"]["notice"];
    EXPECT_EQ(reports["twice"]["pieces"][0]["placement"], reports["once"]["pieces"][0]["placement"]);
    EXPECT_EQ(reports["twice"]["undo"], reports["once"]["undo"]);
}

// Every edit of the pieces the window makes (a move, a push, a placement applied, duplicate,
// split, merge, undo and redo, delete) and a stroke on another piece land in the stroke log, and
// `sculpt apply` of it on the document the window opened gives every piece bit for bit: its
// voxels, name and placement.
TEST(HeadlessTools, PieceEditsReplayWithSculptApplyToEveryPieceBitForBit)
{
    TempDir dir;
    const std::vector<Piece> pieces = bodyAndBallApart();
    writeVdbPieces(pieces, dir / "two.vdb");
    const fs::path r = dir / "r.jsonl";
    UiEvents events;
    const auto moveX = [&events](const std::string& amount) {
        events.key("G").key("X");
        for (char digit : amount) events.key(std::string(1, digit));
        events.key("Enter").untilJobEnds();
    };
    events.untilJobEnds().key("Tab");
    moveX("5");
    events.key("P");
    moveX("12");  // into the ball: it is dented aside
    events.report(r, "pushed").key("A", {"ctrl"}).untilJobEnds().report(r, "applied");
    events.key("D", {"shift"}).untilJobEnds().report(r, "duplicated");
    events.key("P", {"alt"}).untilJobEnds().key("J", {"ctrl"}).untilJobEnds().report(r, "merged");
    events.key("Z", {"ctrl"}).key("Z", {"ctrl", "shift"}).key("Delete").report(r, "deleted");
    events.key("Tab").key("Home").drag(kCentreX - 40, kCentreY, kCentreX + 40, kCentreY + 20).report(r, "end");
    ui::AppOptions options = headlessOptions(dir, (dir / "two.vdb").string());
    options.strokeLog = dir / "strokes.json";
    ASSERT_EQ(playHeadless(dir, events, options), 0);
    const Reports reports(r);
    EXPECT_NE(reports["pushed"]["pieces"][1]["checksum"], formatChecksum(gridChecksum(pieces[1].field.grid())))
        << "the ball was dented";
    EXPECT_EQ(reports["duplicated"]["pieces"].size(), 3u);
    EXPECT_EQ(reports["merged"]["pieces"].size(), 2u);
    EXPECT_EQ(reports["deleted"]["pieces"].size(), 1u);
    EXPECT_GT(reports["end"]["undo"].get<int>(), reports["deleted"]["undo"].get<int>()) << "the stroke landed";

    const CommandResult apply = runSculpt("apply two.vdb strokes.json -o applied.vdb", dir.path().string());
    ASSERT_EQ(apply.exitCode, 0) << apply.err;
    const VdbPieces replayed = readVdbPieces(dir / "applied.vdb");
    const nlohmann::json& window = reports["end"]["pieces"];
    ASSERT_EQ(replayed.pieces.size(), window.size());
    for (std::size_t i = 0; i < replayed.pieces.size(); ++i) {
        const Piece& piece = replayed.pieces[i];
        EXPECT_EQ(formatChecksum(gridChecksum(piece.field.grid())), window[i]["checksum"]) << piece.name;
        EXPECT_EQ(piece.name, window[i]["name"]);
        std::vector<double> placement(piece.placement.asPointer(), piece.placement.asPointer() + 16);
        EXPECT_EQ(nlohmann::json(placement), window[i]["placement"]) << piece.name;
    }
}

}  // namespace
}  // namespace sculpt::test
