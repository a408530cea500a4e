// The window's tools driven by input events in a headless SculptApp (no display): a brush stroke
// and its undo, a lasso cut, a box mask, a piece moved into another (stopping at contact, then
// pushing it aside); each grid checked against `sculpt apply` of the window's stroke log or the
// properties the Xvfb replays assert.

#include "core/field/grid_checksum.h"
#include "core/io/vdb_file.h"
#include "core/primitives/analytic_shapes.h"
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
    for (int i = 1; i <= 40; ++i) {
        const double a = 2.0 * M_PI * i / 40;
        events.move(cx + 200 * std::cos(a), cy + 140 * std::sin(a));
    }
    events.release().untilJobEnds().report(r, "cut");
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
    ASSERT_EQ(playHeadless(dir, events, ballWithLog(dir)), 0);
    const Reports reports(r);
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

double placedX(const nlohmann::json& piece) { return piece["placement"][12].get<double>(); }  // row 3: translation

TEST(HeadlessTools, APieceMovedIntoAnotherStopsAtContactAndAPushIsOneUndoStep)
{
    TempDir dir;
    std::vector<Piece> pieces{{{"body"}, makeSphere(10.0, 0.5)}, {{"ball", {0.9f, 0.3f, 0.2f}}, makeSphere(6.0, 0.5)}};
    pieces[1].placement.setTranslation(openvdb::Vec3d(30.0, 0.0, 0.0));  // 14 apart: body to x = 10, ball from 24
    writeVdbPieces(pieces, dir / "two.vdb");
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

}  // namespace
}  // namespace sculpt::test
