// SPDX-License-Identifier: Apache-2.0
// sculpt-ui end to end, under Xvfb with Mesa: every test replays recorded input (--play)
// through the same code as live input and reads what the program reported and drew.

#include "core/field/grid_checksum.h"
#include "core/field/surface_mask.h"
#include "core/io/mesh_import.h"
#include "core/io/vdb_file.h"
#include "core/io/vdb_layout.h"
#include "core/primitives/analytic_shapes.h"
#include "tests/support/file_bytes.h"
#include "tests/support/grid_builders.h"
#include "tests/support/temp_dir.h"
#include "tests/support/vdb_files.h"
#include "tests/ui/ui_driver.h"

#include <sys/stat.h>

#include <gtest/gtest.h>
#include <openvdb/io/File.h>
#include <openvdb/tools/LevelSetMeasure.h>
#include <vtkImageData.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iterator>
#include <thread>

namespace sculpt::test {
namespace {

namespace fs = std::filesystem;

/// The default clay ball (radius 50 at the origin) seen at 1280x800 in the opening view.
constexpr double kCentreX = 640, kCentreY = 400;

std::string shellQuoted(const fs::path& p) { return "'" + p.string() + "'"; }

/// Replays `events` on `document` (empty: the clay ball) with a private state directory.
CommandResult play(const TempDir& dir, const UiEvents& events, const std::string& document = "",
                   const std::string& extra = "")
{
    events.write(dir / "events.json");
    return runUi((document.empty() ? "" : shellQuoted(document) + " ") + "--play " + shellQuoted(dir / "events.json") +
                     " --state-dir " + shellQuoted(dir / "state") + " " + extra,
                 dir.path().string());
}

std::string checksumOfFile(const fs::path& path) { return formatChecksum(gridChecksum(readFieldImage(path).grid())); }

/// `sculpt apply` of the window's stroke log (strokes.json) on `start` writes the grid the window
/// reported.
void expectApplyGives(const TempDir& dir, const std::string& start, const std::string& checksum)
{
    const CommandResult apply = runSculpt("apply " + start + " strokes.json -o applied.vdb", dir.path().string());
    ASSERT_EQ(apply.exitCode, 0) << apply.err;
    EXPECT_EQ(checksumOfFile(dir / "applied.vdb"), checksum);
}

TEST(SculptUi, TheOpeningViewShowsTheClayBall)
{
    TempDir dir;
    const CommandResult run =
        runUi("--screenshot " + shellQuoted(dir / "open.png") + " --state-dir " + shellQuoted(dir / "state"),
              dir.path().string());
    ASSERT_EQ(run.exitCode, 0) << run.err;
    vtkSmartPointer<vtkImageData> image = readPng(dir / "open.png");
    const int* d = image->GetDimensions();
    ASSERT_EQ(d[0], 1280);
    ASSERT_EQ(d[1], 800);
    const auto* p = static_cast<const unsigned char*>(image->GetScalarPointer());
    const int channels = image->GetNumberOfScalarComponents();
    std::size_t clay = 0, first = 0;
    const std::size_t pixels = std::size_t(d[0]) * std::size_t(d[1]);
    for (std::size_t i = 0; i < pixels; ++i) {
        const int r = p[i * channels], g = p[i * channels + 1], b = p[i * channels + 2];
        if (r > g && g > b && r - b > 40) ++clay;  // warm clay, not the grey background or panels
        if (r == p[0] && g == p[1] && b == p[2]) ++first;
    }
    EXPECT_LT(double(first) / double(pixels), 0.9) << "one colour";
    // A ball of 330 pixels radius: pi 330^2 / (1280 x 800) = 33% of the frame.
    EXPECT_GT(double(clay) / double(pixels), 0.2);
    EXPECT_LT(double(clay) / double(pixels), 0.5);
}

TEST(SculptUi, TheCursorPicksTheSphereWithinHalfAVoxelAndNothingOffIt)
{
    TempDir dir;
    UiEvents events;
    const std::pair<double, double> onTheBall[] = {
        {kCentreX, kCentreY}, {560.0, 330.0}, {800.0, 520.0}, {900.0, 260.0}};
    for (const auto& [x, y] : onTheBall) events.move(x, y).report(dir / "r.jsonl", "at " + std::to_string(int(x)));
    events.move(1150, 600).report(dir / "r.jsonl", "beside");  // beside the ball, under no panel
    const CommandResult run = play(dir, events);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Reports reports(dir / "r.jsonl");
    ASSERT_EQ(reports.size(), 5u);
    for (const auto& [x, y] : onTheBall) {
        const nlohmann::json& at = reports["at " + std::to_string(int(x))];
        ASSERT_TRUE(at["pick"]["hit"].get<bool>()) << x;
        const auto& p = at["pick"]["position"];
        const double radius =
            std::sqrt(p[0].get<double>() * p[0].get<double>() + p[1].get<double>() * p[1].get<double>() +
                      p[2].get<double>() * p[2].get<double>());
        EXPECT_NEAR(radius, 50.0, 0.25) << "pick at " << x;  // half a voxel of 0.5
        EXPECT_GT(p[2].get<double>(), 0.0) << "the front of the ball faces the camera";
        const auto& n = at["pick"]["normal"];
        EXPECT_NEAR(n[0].get<double>() * p[0].get<double>() / radius +
                        n[1].get<double>() * p[1].get<double>() / radius +
                        n[2].get<double>() * p[2].get<double>() / radius,
                    1.0, 0.01);
    }
    EXPECT_FALSE(reports["beside"]["pick"]["hit"].get<bool>());
}

TEST(SculptUi, AddAndCarveDragsChangeTheVolumeAndCtrlZRestoresTheGridBitForBit)
{
    TempDir dir;
    const fs::path r = dir / "r.jsonl";
    UiEvents events;
    events.move(560, 380).report(r, "before").screenshot(dir / "before.png");
    events.drag(560, 380, 720, 400).move(1150, 600).report(r, "added").screenshot(dir / "added.png");
    events.key("Z", {"ctrl"}).report(r, "add-undone");
    events.key("C").drag(560, 380, 720, 400).report(r, "carved");  // carve tool
    events.key("Z", {"ctrl"}).report(r, "carve-undone");
    events.key("A").drag(600, 300, 700, 300, 10, {"ctrl"}).report(r, "ctrl-add");  // add with Ctrl: carves
    events.key("Z", {"ctrl"}).key("Z", {"ctrl", "shift"}).report(r, "redone");     // undo, redo
    const CommandResult run = play(dir, events);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Reports reports(r);
    ASSERT_EQ(reports.size(), 7u);
    const std::string original = reports["before"]["checksum"];
    const double volume = reports["before"]["volume"];
    EXPECT_GT(reports["added"]["volume"].get<double>(), volume + 100.0);
    EXPECT_EQ(reports["added"]["undo"], 1);
    EXPECT_TRUE(reports["added"]["modified"].get<bool>());
    EXPECT_GT(differingShare(readPng(dir / "before.png"), readPng(dir / "added.png")), 0.002);
    EXPECT_EQ(reports["add-undone"]["checksum"], original);
    EXPECT_FALSE(reports["add-undone"]["modified"].get<bool>());
    EXPECT_LT(reports["carved"]["volume"].get<double>(), volume - 100.0);
    EXPECT_EQ(reports["carve-undone"]["checksum"], original);
    EXPECT_LT(reports["ctrl-add"]["volume"].get<double>(), volume - 10.0);
    EXPECT_EQ(reports["redone"]["checksum"], reports["ctrl-add"]["checksum"]);  // redo is bit-exact too
    EXPECT_EQ(reports["redone"]["euler"], 2);
    EXPECT_EQ(reports["redone"]["shells"], 1);
}

// View > Clip Plane across x, seen from +x: the cap is the ball's section from its field (pi r^2
// within 0.5%), the pointer picks the cap (its normal the plane's), a carve there tunnels into
// the clay under the cap, and Off shows the whole ball again.
TEST(SculptUi, TheClipPlaneCapsTheCutWithTheExactSectionAndStrokesLandOnTheCap)
{
    TempDir dir;
    const fs::path r = dir / "r.jsonl";
    UiEvents events;
    events.key("C", {"alt"}).key("3").move(kCentreX, kCentreY).report(r, "capped");
    events.drag(kCentreX - 40, kCentreY, kCentreX + 40, kCentreY, 10, {"ctrl"}).move(kCentreX, kCentreY);
    events.report(r, "carved").screenshot(dir / "cap.png");
    // From the front, a stroke on the half shown, far from the plane: its cap is not made again.
    events.key("1").drag(kCentreX - 200, kCentreY, kCentreX - 170, kCentreY + 20).report(r, "away");
    for (int i = 0; i < 4; ++i) events.key("C", {"alt"});
    events.report(r, "off");
    const CommandResult run = play(dir, events);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Reports reports(r);
    const nlohmann::json& capped = reports["capped"];
    EXPECT_EQ(capped["clip"], "x (left-right)");
    EXPECT_NEAR(capped["cap_area"].get<double>(), M_PI * 2500.0, 0.005 * M_PI * 2500.0);
    ASSERT_TRUE(capped["pick"]["hit"].get<bool>());
    EXPECT_NEAR(capped["pick"]["normal"][0].get<double>(), 1.0, 1e-9) << "the cap, not the sphere behind it";
    EXPECT_NEAR(capped["pick"]["position"][0].get<double>(), capped["clip_offset"].get<double>(), 1e-6);
    // The carve landed on the cap: clay went, and the cap lost the tunnel's section.
    EXPECT_LT(reports["carved"]["volume"].get<double>(), capped["volume"].get<double>() - 100.0);
    EXPECT_LT(reports["carved"]["cap_area"].get<double>(), capped["cap_area"].get<double>() - 50.0);
    EXPECT_EQ(reports["carved"]["undo"], 1);
    EXPECT_GT(reports["away"]["volume"].get<double>(), reports["carved"]["volume"].get<double>() + 10.0);
    EXPECT_EQ(reports["away"]["cap_remakes"], reports["carved"]["cap_remakes"]) << "a stroke away from the plane";
    EXPECT_GT(reports["carved"]["cap_remakes"].get<int>(), reports["capped"]["cap_remakes"].get<int>());
    EXPECT_EQ(reports["off"]["clip"], "Off");
    EXPECT_EQ(reports["off"]["cap_area"], 0.0);
}

// View > Slices on an imported scan: the kept scan's three planes through the scan's centre with
// the surface's contour on each; a click in the axial view moves the cursor within that plane, a
// right drag changes the window and level, the wheel steps the sagittal plane by a sample, and a
// click on the model puts the cursor where the pointer picks it. A document keeping no scan says
// so instead.
TEST(SculptUi, TheSlicesViewShowsTheKeptScanWithContoursLinkedToTheModel)
{
    TempDir dir;
    const int n = 64;
    std::string bytes(std::size_t(n * n * n), '\0');
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                bytes[std::size_t((k * n + j) * n + i)] = std::hypot(i - 31.5, j - 31.5, k - 31.5) < 20.0 ? 100 : 0;
    std::ofstream(dir / "ball.raw", std::ios::binary) << bytes;
    const CommandResult import =
        runSculpt("import ball.raw --raw-dims 64,64,64 --raw-type uint8 --iso 50 -o ball.vdb", dir.path().string());
    ASSERT_EQ(import.exitCode, 0) << import.err;

    const fs::path r = dir / "r.jsonl";
    const double axialX = 382, axialY = 645, sagittalX = 898;  // the views' centres at 1280 x 800
    UiEvents events;
    events.key("V", {"alt"}).move(640, 200).report(r, "shown").screenshot(dir / "slices.png");
    events.move(axialX + 30, axialY - 20).press().release().report(r, "clicked");
    events.move(axialX + 260, axialY).press("right").move(axialX + 300, axialY + 30).release("right");
    events.report(r, "levelled");
    events.move(sagittalX, axialY).wheel(4).report(r, "stepped");
    events.move(640, 250).report(r, "over-model").press().release().report(r, "model-clicked");
    const CommandResult run = play(dir, events, (dir / "ball.vdb").string());
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Reports reports(r);

    const nlohmann::json& shown = reports["shown"]["slices"];
    ASSERT_TRUE(shown["shown"].get<bool>()) << reports["shown"]["error"];
    for (const char* view : {"Axial", "Coronal", "Sagittal"}) EXPECT_GT(shown[view].get<int>(), 50) << view;
    const auto cursor = [&](const char* name, int a) { return reports[name]["slices"]["cursor"][a].get<double>(); };
    EXPECT_NEAR(cursor("shown", 0), 31.5, 0.5);  // the scan's centre: the raw file's origin is sample 0
    EXPECT_NE(cursor("clicked", 0), cursor("shown", 0));
    EXPECT_NE(cursor("clicked", 1), cursor("shown", 1));
    EXPECT_EQ(cursor("clicked", 2), cursor("shown", 2)) << "a click in the axial view keeps its plane";
    EXPECT_GT(cursor("clicked", 0), cursor("shown", 0)) << "right on the screen is the patient's left: +x";
    EXPECT_LT(cursor("clicked", 1), cursor("shown", 1)) << "up on the screen is the front: -y";
    const nlohmann::json& before = reports["clicked"]["slices"];
    const nlohmann::json& after = reports["levelled"]["slices"];
    EXPECT_GT(after["window"].get<double>(), before["window"].get<double>());
    EXPECT_LT(after["level"].get<double>(), before["level"].get<double>());
    EXPECT_NEAR(cursor("stepped", 0), cursor("levelled", 0) + 4.0, 1e-9) << "four samples of 1 mm";
    const nlohmann::json& pick = reports["over-model"]["pick"];
    ASSERT_TRUE(pick["hit"].get<bool>());
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(cursor("model-clicked", a), pick["position"][a].get<double>(), 1e-9);

    TempDir plain;
    UiEvents none;
    none.key("V", {"alt"}).report(plain / "r.jsonl", "refused");
    ASSERT_EQ(play(plain, none).exitCode, 0);
    const Reports plainReports(plain / "r.jsonl");
    const nlohmann::json& refused = plainReports["refused"];
    EXPECT_FALSE(refused["slices"]["shown"].get<bool>());
    EXPECT_NE(refused.dump().find("keeps no scan"), std::string::npos) << refused.dump();
}

TEST(SculptUi, AStampReuploadsOnlyTheBlocksTheMesherChanged)
{
    TempDir dir;
    const fs::path r = dir / "r.jsonl";
    UiEvents events;
    events.move(600, 380).report(r, "before").press().report(r, "pressed").release().report(r, "released");
    const CommandResult run = play(dir, events);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Reports reports(r);
    ASSERT_EQ(reports.size(), 3u);
    const std::size_t uploaded = reports["pressed"]["uploaded"], changed = reports["pressed"]["mesher_changed"];
    const std::size_t blocks = reports["pressed"]["blocks"];
    EXPECT_GT(uploaded, 0u);
    EXPECT_EQ(uploaded + reports["pressed"]["removed"].get<std::size_t>(), changed);
    EXPECT_LT(double(uploaded), 0.05 * double(blocks)) << uploaded << " of " << blocks;
    // The display re-uploads the chunks holding those blocks, and no others.
    const std::size_t chunks = reports["pressed"]["chunks"], chunksUploaded = reports["pressed"]["chunks_uploaded"];
    EXPECT_GT(chunksUploaded, 0u);
    EXPECT_LE(chunksUploaded, uploaded + reports["pressed"]["removed"].get<std::size_t>());
    EXPECT_LT(double(chunksUploaded), 0.2 * double(chunks)) << chunksUploaded << " of " << chunks;
    EXPECT_NE(reports["pressed"]["checksum"], reports["before"]["checksum"]);  // stamped on the press, before any frame
}

TEST(SculptUi, AStrokeRecordedInTheUiReplaysBitForBitWithSculptApply)
{
    TempDir dir;
    ASSERT_EQ(runSculpt("new -o ball.vdb", dir.path().string()).exitCode, 0);
    UiEvents events;
    events.key("X")
        .drag(600, 330, 760, 470, 25)
        .key("I")
        .drag(500, 450, 640, 300, 15)
        .key("S")
        .drag(560, 350, 700, 360, 10);
    events.key("Z", {"ctrl"}).key("G").drag(640, 300, 660, 250, 8).key("P").drag(520, 500, 700, 520, 10);
    events.key("B").drag(700, 300, 720, 310, 3).report(dir / "r.jsonl", "end");
    const CommandResult run =
        play(dir, events, (dir / "ball.vdb").string(),
             "--stroke-log " + shellQuoted(dir / "strokes.json") + " --save-as " + shellQuoted(dir / "ui.vdb"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const CommandResult apply = runSculpt("apply ball.vdb strokes.json -o applied.vdb", dir.path().string());
    ASSERT_EQ(apply.exitCode, 0) << apply.err;
    EXPECT_NE(apply.out.find("6 strokes"), std::string::npos) << apply.out;
    const std::string ui = Reports(dir / "r.jsonl")["end"]["checksum"];
    EXPECT_EQ(checksumOfFile(dir / "ui.vdb"), ui);
    EXPECT_EQ(checksumOfFile(dir / "applied.vdb"), ui);
    EXPECT_NE(checksumOfFile(dir / "ball.vdb"), ui);
}

TEST(SculptUi, StrokesOnASlowMachineFollowEveryEventToTheSameGridBitForBit)
{
    TempDir dir;
    ASSERT_EQ(runSculpt("new -o ball.vdb", dir.path().string()).exitCode, 0);
    const fs::path r = dir / "r.jsonl";
    UiEvents events;  // 20 ms apart: with 250 ms added to each frame, a dozen events come per frame
    events.report(r, "start").drag(560, 330, 760, 470, 30).key("S").drag(700, 450, 540, 350, 20);
    events.report(r, "end");
    const std::string save = " --save-as ";
    ASSERT_EQ(play(dir, events, (dir / "ball.vdb").string(), save + shellQuoted(dir / "fast.vdb")).exitCode, 0);
    const std::size_t fastFrames =
        Reports(r)["end"]["frame"].get<std::size_t>() - Reports(r)["start"]["frame"].get<std::size_t>();
    fs::remove(r);
    const CommandResult slow = play(dir, events, (dir / "ball.vdb").string(),
                                    "--slow-frames 250 --stroke-log " + shellQuoted(dir / "strokes.json") + save +
                                        shellQuoted(dir / "slow.vdb"));
    ASSERT_EQ(slow.exitCode, 0) << slow.err;
    const Reports reports(r);
    const std::size_t slowFrames =
        reports["end"]["frame"].get<std::size_t>() - reports["start"]["frame"].get<std::size_t>();
    EXPECT_LT(slowFrames, fastFrames);
    EXPECT_LT(4 * slowFrames, 50u) << "the 50 moves should have come four and more to a frame";
    EXPECT_EQ(reports["end"]["undo"], 2);
    ASSERT_EQ(runSculpt("apply ball.vdb strokes.json -o applied.vdb", dir.path().string()).exitCode, 0);
    const std::string slowGrid = reports["end"]["checksum"];
    EXPECT_EQ(checksumOfFile(dir / "slow.vdb"), slowGrid);
    EXPECT_EQ(checksumOfFile(dir / "fast.vdb"), slowGrid);
    EXPECT_EQ(checksumOfFile(dir / "applied.vdb"), slowGrid);
    EXPECT_NE(checksumOfFile(dir / "ball.vdb"), slowGrid);
}

TEST(SculptUi, ARecordingReplaysToTheSameGridAndAResizeResizesTheView)
{
    TempDir dir;
    UiEvents events;
    events.key("I").drag(560, 380, 700, 420, 12).key("RightBracket").drag(600, 300, 660, 320, 6, {"ctrl"});
    events.report(dir / "r.jsonl", "strokes").resize(800, 600).screenshot(dir / "small.png");
    ASSERT_EQ(play(dir, events, "", "--record " + shellQuoted(dir / "recorded.json")).exitCode, 0);
    EXPECT_EQ(readPng(dir / "small.png")->GetDimensions()[0], 800);
    EXPECT_EQ(readPng(dir / "small.png")->GetDimensions()[1], 600);
    // The recording holds every input (no report, no screenshot): replayed, it makes the same grid.
    const CommandResult again =
        runUi("--play recorded.json --state-dir state --save-as replayed.vdb", dir.path().string());
    ASSERT_EQ(again.exitCode, 0) << again.err;
    const auto report = Reports(dir / "r.jsonl")["strokes"];
    EXPECT_EQ(report["undo"], 2);  // both strokes landed
    const std::string made = report["checksum"];
    EXPECT_EQ(checksumOfFile(dir / "replayed.vdb"), made);
}

TEST(SculptUi, SaveExportAndOpenThroughTheirPromptsAndACorruptFileChangesNothing)
{
    TempDir dir;
    const fs::path r = dir / "r.jsonl";
    std::ofstream(dir / "corrupt.vdb") << "not a vdb file at all";
    UiEvents events;
    events.drag(560, 380, 700, 380)
        .key("S", {"ctrl"})
        .text((dir / "saved.vdb").string())
        .key("Enter")
        .report(r, "saved");
    // Exporting and opening are jobs: the replay waits for each.
    events.key("E", {"ctrl"}).key("A", {"ctrl"}).text((dir / "saved.stl").string()).key("Enter").untilJobEnds();
    events.key("O", {"ctrl"})
        .text((dir / "corrupt.vdb").string())
        .key("Enter")
        .untilJobEnds()
        .report(r, "corrupt-refused");
    events.key("Enter");  // dismisses the error
    events.key("O", {"ctrl"}).text((dir / "saved.vdb").string()).key("Enter").untilJobEnds().report(r, "reopened");
    const CommandResult run = play(dir, events);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Reports reports(r);
    ASSERT_EQ(reports.size(), 3u);
    EXPECT_FALSE(reports["saved"]["modified"].get<bool>());
    EXPECT_EQ(reports["saved"]["title"], "saved.vdb");
    EXPECT_EQ(checksumOfFile(dir / "saved.vdb"), reports["saved"]["checksum"]);
    const CommandResult info = runSculpt("info saved.vdb", dir.path().string());
    EXPECT_EQ(info.exitCode, 0) << info.err;
    ASSERT_TRUE(fs::exists(dir / "saved.stl"));
    EXPECT_GT(fs::file_size(dir / "saved.stl"), 84u + 50u * 100000u);  // binary STL of ~390k triangles

    EXPECT_NE(reports["corrupt-refused"]["error"].get<std::string>().find("corrupt.vdb"), std::string::npos)
        << reports["corrupt-refused"].dump();
    EXPECT_EQ(reports["corrupt-refused"]["checksum"], reports["saved"]["checksum"]);
    EXPECT_EQ(reports["corrupt-refused"]["title"], "saved.vdb");
    EXPECT_EQ(reports["reopened"]["error"], "");
    EXPECT_EQ(reports["reopened"]["checksum"], reports["saved"]["checksum"]);
    EXPECT_EQ(reports["reopened"]["undo"], 0);  // a freshly opened document
}

// A document dropped on the window opens; with unsaved changes "save changes?" comes first, then
// the Open prompt holds the dropped path. A mesh dropped goes to Import.
TEST(SculptUi, AFileDroppedOnTheWindowOpensOrImports)
{
    TempDir dir;
    const fs::path r = dir / "r.jsonl";
    ASSERT_EQ(runSculpt("new --shape box --radius 20 --voxel-size 1 -o box.vdb", dir.path().string()).exitCode, 0);
    ASSERT_EQ(runSculpt("new --shape torus --radius 20 --voxel-size 1 -o ring.vdb --mesh ring.stl", dir.path().string())
                  .exitCode,
              0);
    UiEvents events;
    events.drop(dir / "box.vdb").untilJobEnds().report(r, "box");
    events.drag(560, 380, 700, 380).drop(dir / "ring.vdb").report(r, "asking").key("D").report(r, "prompt");
    events.key("Enter").untilJobEnds().report(r, "ring");
    events.drop(dir / "ring.stl").untilJobEnds().report(r, "import");
    const CommandResult run = play(dir, events);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Reports reports(r);
    EXPECT_EQ(reports["box"]["title"], "box.vdb");
    EXPECT_EQ(reports["box"]["checksum"], checksumOfFile(dir / "box.vdb"));
    EXPECT_TRUE(reports["asking"]["asking_unsaved"].get<bool>());
    EXPECT_EQ(reports["asking"]["title"], "box.vdb *");
    EXPECT_EQ(reports["prompt"]["prompt"], "open");
    EXPECT_EQ(reports["prompt"]["prompt_path"], (dir / "ring.vdb").string());
    EXPECT_EQ(reports["ring"]["title"], "ring.vdb");
    EXPECT_EQ(reports["ring"]["checksum"], checksumOfFile(dir / "ring.vdb"));
    EXPECT_EQ(reports["import"]["mode"], "import") << reports["import"].dump();
}

TEST(SculptUi, TheFileChooserListsTheFoldersAndDocumentsAndTabCompletesThePathToOpen)
{
    TempDir dir;
    const fs::path work = dir / "work";
    fs::create_directories(work / "scans");
    ASSERT_EQ(runSculpt("new --radius 20 -o sphere_model.vdb", work).exitCode, 0);
    std::ofstream(work / "notes.txt") << "not listed by Open";
    const fs::path r = dir / "r.jsonl";
    UiEvents events;
    events.key("O", {"ctrl"}).text(work.string() + "/sph").key("Tab").wait(0.3);
    events.screenshot(dir / "chooser.png").report(r, "completed");
    events.key("Enter").untilJobEnds().report(r, "opened");
    const CommandResult run = play(dir, events);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Reports reports(r);
    EXPECT_EQ(reports["completed"]["prompt"], "open");
    EXPECT_EQ(reports["completed"]["prompt_path"], (work / "sphere_model.vdb").string());
    EXPECT_EQ(reports["completed"]["listed"], 2) << "scans/ and sphere_model.vdb, not notes.txt";
    EXPECT_EQ(reports["opened"]["title"], "sphere_model.vdb") << reports["opened"]["error"];
    EXPECT_EQ(reports["opened"]["checksum"], checksumOfFile(work / "sphere_model.vdb"));
}

TEST(SculptUi, AFileOfSeveralLevelSetsAsksWhichToSculptAndKeepsTheOthers)
{
    TempDir dir;
    const FieldImage left = makeSphere(8.0, 0.5), right = makeSphere(14.0, 0.5);
    openvdb::MetaMap meta;
    meta.insertMeta("creator", openvdb::StringMetadata("Houdini 20"));
    test::writeNamedGrids(dir / "pair.vdb", {{"left", left}, {"right", right}}, meta);
    const std::string leftSum = formatChecksum(gridChecksum(left.grid()));

    const fs::path r = dir / "r.jsonl";
    UiEvents events;
    events.key("O", {"ctrl"}).text((dir / "pair.vdb").string()).key("Enter").wait(0.3);
    events.screenshot(dir / "choice.png").report(r, "asking").key("2").untilJobEnds().report(r, "opened-right");
    events.drag(560, 380, 700, 380).key("S", {"ctrl"}).report(r, "saved");
    const CommandResult run = play(dir, events);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Reports reports(r);
    ASSERT_EQ(reports.size(), 3u);
    EXPECT_EQ(reports["asking"]["title"], "untitled");  // asking, nothing opened yet
    EXPECT_EQ(reports["opened-right"]["title"], "pair.vdb");
    EXPECT_EQ(reports["opened-right"]["checksum"], formatChecksum(gridChecksum(right.grid())));
    EXPECT_FALSE(reports["saved"]["modified"].get<bool>());

    const VdbLayout saved = scanVdbLayout(dir / "pair.vdb");
    ASSERT_EQ(saved.grids.size(), 2u);
    EXPECT_EQ(saved.editedGrid, "right");
    EXPECT_EQ(checksumOfFile(dir / "pair.vdb"), reports["saved"]["checksum"]);
    EXPECT_NE(reports["saved"]["checksum"], reports["opened-right"]["checksum"]);  // the stroke is in the file
    openvdb::io::File file((dir / "pair.vdb").string());
    file.open();
    EXPECT_EQ(file.getMetadata()->metaValue<std::string>("creator"), "Houdini 20");
    EXPECT_EQ(formatChecksum(gridChecksum(*openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid("left")))), leftSum);
}

TEST(SculptUi, AfterAKillTheAutosaveIsOfferedAndRestoresTheGrid)
{
    TempDir dir;
    ASSERT_EQ(runSculpt("new -o ball.vdb", dir.path().string()).exitCode, 0);
    const fs::path state = dir / "state";
    UiEvents first;
    first.drag(560, 380, 700, 420).report(dir / "first.jsonl", "stroke");
    first.write(dir / "first.json");
    const std::string args = shellQuoted(dir / "ball.vdb") + " --play " + shellQuoted(dir / "first.json") +
                             " --state-dir " + shellQuoted(state) + " --autosave-seconds 0.5 --stay";
    BackgroundUi ui(args, dir.path());
    fs::path recovery;
    const auto reported = [&] {  // a whole line: the report is written once its frame is drawn
        std::ifstream in(dir / "first.jsonl");
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        return !text.empty() && text.back() == '\n';
    };
    // Until the autosave exists and the replay has reported (a loaded machine draws slowly).
    for (int i = 0; i < 600 && (recovery.empty() || !reported()); ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        std::error_code ec;
        if (fs::exists(state / "recovery", ec)) {
            for (const auto& entry : fs::directory_iterator(state / "recovery")) {
                const std::string name = entry.path().filename().string();
                if (entry.path().extension() == ".vdb" && name[0] != '.') recovery = entry.path();  // not a temporary
            }
        }
    }
    ASSERT_FALSE(recovery.empty()) << "no autosave within a minute";
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    ASSERT_TRUE(ui.killProgram()) << "the sculpt-ui this test started is not running";
    const Reports firstReports(dir / "first.jsonl");
    ASSERT_EQ(firstReports.size(), 1u);
    ASSERT_TRUE(fs::exists(recovery)) << "a killed program leaves its autosave";

    UiEvents second;
    second.report(dir / "second.jsonl", "offered").key("R").report(dir / "second.jsonl", "recovered");
    const CommandResult run = play(dir, second, (dir / "ball.vdb").string());
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Reports reports(dir / "second.jsonl");
    ASSERT_EQ(reports.size(), 2u);
    EXPECT_TRUE(reports["offered"]["recovery_offered"].get<bool>());
    EXPECT_EQ(reports["offered"]["checksum"], checksumOfFile(dir / "ball.vdb"));
    EXPECT_FALSE(reports["recovered"]["recovery_offered"].get<bool>());
    EXPECT_EQ(reports["recovered"]["checksum"], firstReports["stroke"]["checksum"]);
    EXPECT_TRUE(reports["recovered"]["modified"].get<bool>()) << "recovered work is not saved yet";
}

TEST(SculptUi, NewAndQuitWithUnsavedChangesAskFirst)
{
    TempDir dir;
    const fs::path r = dir / "r.jsonl";
    UiEvents events;
    events.report(r, "start")
        .drag(560, 380, 700, 380)
        .key("N", {"ctrl"})
        .report(r, "asking-new")
        .key("D")
        .report(r, "new-prompt")
        .key("Enter")
        .report(r, "new-ball");
    events.drag(560, 380, 700, 380)
        .quit()
        .report(r, "asking-quit")
        .key("Escape")
        .report(r, "quit-cancelled")
        .quit()
        .key("D")
        .wait(2.0)
        .report(r, "after-discard");
    const CommandResult run = play(dir, events, "", "--stay");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Reports reports(r);
    ASSERT_EQ(reports.size(), 6u) << "the program quit after Discard, before the last report";
    EXPECT_TRUE(reports["asking-new"]["asking_unsaved"].get<bool>());
    EXPECT_NE(reports["asking-new"]["checksum"], reports["start"]["checksum"]);
    EXPECT_EQ(reports["new-prompt"]["prompt"], "new");  // discarded: the New dialog
    EXPECT_EQ(reports["new-ball"]["prompt"], "none");
    EXPECT_EQ(reports["new-ball"]["checksum"], reports["start"]["checksum"]);  // a new clay ball, the default shape
    EXPECT_FALSE(reports["new-ball"]["modified"].get<bool>());
    EXPECT_EQ(reports["new-ball"]["undo"], 0);
    EXPECT_TRUE(reports["asking-quit"]["asking_unsaved"].get<bool>());
    EXPECT_FALSE(reports["quit-cancelled"]["asking_unsaved"].get<bool>());  // Escape cancelled: still running
    EXPECT_TRUE(reports["quit-cancelled"]["modified"].get<bool>());
}

TEST(SculptUi, ClosingTheWindowMidStrokeKeepsTheStrokeAndAsksToSaveIt)
{
    TempDir dir;
    const fs::path r = dir / "r.jsonl";
    UiEvents events;
    events.report(r, "start").move(560, 380).press();
    for (int i = 1; i <= 10; ++i) events.move(560 + 14 * i, 380);
    events.quit().report(r, "closed");  // the window closed with the button still held
    const CommandResult run = play(dir, events);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Reports reports(r);
    ASSERT_EQ(reports.size(), 2u);
    EXPECT_NE(reports["closed"]["checksum"], reports["start"]["checksum"]);
    EXPECT_EQ(reports["closed"]["undo"], 1) << "the stroke ends as one undo step";
    EXPECT_TRUE(reports["closed"]["asking_unsaved"].get<bool>()) << "closing was ignored mid-stroke";
}

TEST(SculptUi, AnInternalErrorSavesTheWorkSaysSoAndTheWindowGoesOn)
{
    TempDir dir;
    const fs::path r = dir / "r.jsonl";
    UiEvents events;
    events.drag(560, 380, 700, 380).fault("bad_alloc").report(r, "bad-alloc").key("Enter");
    events.move(560, 420).press();
    for (int i = 1; i <= 5; ++i) events.move(560 + 20 * i, 420);
    events.fault("openvdb").report(r, "openvdb").release().key("Enter");  // mid-stroke
    events.drag(560, 450, 700, 450).report(r, "after");
    const CommandResult run = play(dir, events);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Reports reports(r);
    ASSERT_EQ(reports.size(), 3u);
    const std::string first = reports["bad-alloc"]["error"];
    EXPECT_EQ(first.rfind("internal error: out of memory", 0), 0u) << first;
    EXPECT_NE(first.find("your work is saved in " + (dir / "state" / "recovery").string()), std::string::npos) << first;
    EXPECT_EQ(reports["bad-alloc"]["undo"], 1);
    const std::string second = reports["openvdb"]["error"];
    EXPECT_EQ(second.rfind("internal error: ", 0), 0u) << second;
    EXPECT_NE(second.find("a fault event"), std::string::npos) << second;
    EXPECT_EQ(reports["openvdb"]["undo"], 2) << "the stroke the error cut short is kept";
    EXPECT_EQ(reports["after"]["error"], "");
    EXPECT_EQ(reports["after"]["undo"], 3) << "the window sculpts on";
    EXPECT_NE(reports["after"]["checksum"], reports["openvdb"]["checksum"]);
    EXPECT_NE(run.err.find("sculpt-ui: internal error"), std::string::npos) << run.err;
}

TEST(SculptUi, AWholeModelSmoothRunsAsAJobTheViewStaysLiveAndCancelChangesNothing)
{
    TempDir dir;
    ASSERT_EQ(runSculpt("new -o clay.vdb", dir.path()).exitCode, 0);
    const fs::path r = dir / "r.jsonl";
    UiEvents events;
    events.report(r, "start").key("S", {"alt"}).text("5000").key("Enter").wait(0.5).report(r, "running");
    for (int i = 0; i < 4; ++i) events.key("Left").wait(0.2);  // orbit while it runs
    events.report(r, "orbited").screenshot(dir / "job.png").key("Escape").untilJobEnds().report(r, "cancelled");
    const CommandResult run = play(dir, events, (dir / "clay.vdb").string());
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Reports reports(r);
    ASSERT_EQ(reports.size(), 4u);
    const std::string original = reports["start"]["checksum"];
    ASSERT_TRUE(reports["running"]["job"].is_object()) << reports["running"].dump();
    EXPECT_EQ(reports["running"]["job"]["label"], "smooth 5000");
    ASSERT_TRUE(reports["orbited"]["job"].is_object()) << "5000 iterations cannot be over in a second";
    // Frames kept coming while the job ran: at least one per orbit.
    EXPECT_GE(reports["orbited"]["frame"].get<int>() - reports["running"]["frame"].get<int>(), 4);
    EXPECT_EQ(reports["orbited"]["checksum"], original);  // the job works on its own copy
    EXPECT_EQ(reports["cancelled"]["last_job"], "cancelled");
    EXPECT_TRUE(reports["cancelled"]["job"].is_null());
    EXPECT_EQ(reports["cancelled"]["checksum"], original);
    EXPECT_EQ(reports["cancelled"]["undo"], 0);
    EXPECT_FALSE(reports["cancelled"]["modified"].get<bool>());
}

/// Of the voxels of `before`'s leaves: those whose mask is 1, those of them that differ in
/// `after`, and the others that differ.
struct MaskedChanges {
    std::size_t held = 0, heldChanged = 0, freeChanged = 0;
};

MaskedChanges maskedChanges(const FieldImage& before, const FieldImage& after)
{
    const MaskReader reader(*before.mask());
    const auto was = before.grid().getConstAccessor(), now = after.grid().getConstAccessor();
    MaskedChanges changes;
    for (auto leaf = before.grid().tree().cbeginLeaf(); leaf; ++leaf)
        for (auto it = leaf->beginValueAll(); it; ++it) {
            const openvdb::Coord ijk = it.getCoord();
            const bool same = was.getValue(ijk) == now.getValue(ijk) && was.isValueOn(ijk) == now.isValueOn(ijk);
            const bool held = reader.at(ijk) >= 1.0;
            changes.held += held;
            (held ? changes.heldChanged : changes.freeChanged) += !same;
        }
    return changes;
}

TEST(SculptUi, AMaskPaintedInTheWindowHoldsItsClayThroughASmoothAndUndoesAsOneStep)
{
    TempDir dir;
    const fs::path r = dir / "r.jsonl";
    UiEvents events;
    events.report(r, "start").key("M");
    for (int i = 0; i < 8; ++i) events.key("RightBracket");  // a brush a third of the ball across
    events.drag(kCentreX - 120, kCentreY - 220, kCentreX - 120, kCentreY + 220, 40).move(1150, 600);
    events.report(r, "masked").screenshot(dir / "masked.png");
    events.key("S", {"ctrl"}).text((dir / "masked.vdb").string()).key("Enter");
    events.key("S", {"alt"}).text("10").key("Enter").untilJobEnds().report(r, "smoothed");
    events.key("Z", {"ctrl"}).report(r, "undo-smooth").key("Z", {"ctrl"}).report(r, "undo-mask");
    events.key("Z", {"ctrl", "shift"}).key("Z", {"ctrl", "shift"}).report(r, "redone");
    const CommandResult run = play(dir, events, "", "--save-as " + shellQuoted(dir / "smoothed.vdb"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Reports reports(r);
    EXPECT_EQ(reports["start"]["mask_checksum"], "");
    EXPECT_NE(reports["masked"]["mask_checksum"], "");
    EXPECT_EQ(reports["masked"]["checksum"], reports["start"]["checksum"]) << "painting the mask moves no clay";
    EXPECT_EQ(reports["masked"]["undo"], 1);
    EXPECT_EQ(reports["smoothed"]["undo"], 2);
    EXPECT_EQ(reports["undo-smooth"]["checksum"], reports["masked"]["checksum"]);
    EXPECT_EQ(reports["undo-smooth"]["mask_checksum"], reports["masked"]["mask_checksum"]);
    EXPECT_EQ(reports["undo-mask"]["mask_checksum"], "");
    EXPECT_EQ(reports["redone"]["checksum"], reports["smoothed"]["checksum"]);
    EXPECT_EQ(reports["redone"]["mask_checksum"], reports["masked"]["mask_checksum"]);

    const FieldImage masked = readFieldImage(dir / "masked.vdb"), smoothed = readFieldImage(dir / "smoothed.vdb");
    ASSERT_NE(masked.mask(), nullptr) << "the mask is saved with the document";
    ASSERT_NE(smoothed.mask(), nullptr);
    EXPECT_EQ(gridChecksum(*smoothed.mask()), gridChecksum(*masked.mask()));
    const MaskedChanges changes = maskedChanges(masked, smoothed);
    EXPECT_GT(changes.held, 1000u) << "the stroke masked some clay fully";
    EXPECT_EQ(changes.heldChanged, 0u) << "the masked clay is bit for bit as it was";
    EXPECT_GT(changes.freeChanged, 1000u) << "the rest was smoothed";
}

// A lasso drawn round the ball's right side cuts it away through the model (a job, one undo
// step); a line cut then takes off what lies below a line, mirrored across x; the stroke log
// replays both with `sculpt apply` to the same grid.
TEST(SculptUi, LassoAndLineCutsAreOneUndoStepEachAndReplayWithSculptApply)
{
    TempDir dir;
    ASSERT_EQ(runSculpt("new -o ball.vdb", dir.path().string()).exitCode, 0);
    const fs::path r = dir / "r.jsonl";
    UiEvents events;
    const double cx = kCentreX + 250, cy = kCentreY;  // an ellipse over the ball's right edge
    events.report(r, "start").key("J").move(cx + 200, cy).press().ellipse(cx, cy, 200, 140);
    events.release().untilJobEnds().report(r, "lassoed").screenshot(dir / "lassoed.png");
    events.key("Z", {"ctrl"}).report(r, "undone").key("Z", {"ctrl", "shift"}).report(r, "redone");
    events.key("X").key("J", {"alt"}).drag(kCentreX - 300, kCentreY + 120, kCentreX + 300, kCentreY + 120, 10);
    events.untilJobEnds().report(r, "lined").screenshot(dir / "lined.png");
    const CommandResult run =
        play(dir, events, (dir / "ball.vdb").string(), "--stroke-log " + shellQuoted(dir / "strokes.json"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Reports reports(r);
    const double start = reports["start"]["volume"];
    EXPECT_EQ(reports["lassoed"]["undo"], 1);
    EXPECT_LT(reports["lassoed"]["volume"].get<double>(), 0.9 * start);
    EXPECT_GT(reports["lassoed"]["volume"].get<double>(), 0.5 * start);
    EXPECT_EQ(reports["lassoed"]["shells"], 1);
    EXPECT_EQ(reports["undone"]["checksum"], reports["start"]["checksum"]);
    EXPECT_EQ(reports["redone"]["checksum"], reports["lassoed"]["checksum"]);
    EXPECT_EQ(reports["lined"]["undo"], 2);
    EXPECT_LT(reports["lined"]["volume"].get<double>(), reports["lassoed"]["volume"].get<double>());
    expectApplyGives(dir, "ball.vdb", reports["lined"]["checksum"]);
}

TEST(SculptUi, ABoxMaskAndADrainHoleDrilledAtThePointerAreOneUndoStepEachAndReplayWithSculptApply)
{
    TempDir dir;
    ASSERT_EQ(runSculpt("new -o ball.vdb", dir.path()).exitCode, 0);
    ASSERT_EQ(runSculpt("hollow ball.vdb --thickness 2 -o shell.vdb", dir.path()).exitCode, 0);
    const fs::path r = dir / "r.jsonl";
    UiEvents events;
    events.report(r, "start").key("B", {"shift"}).drag(kCentreX - 380, kCentreY - 300, kCentreX - 120, kCentreY + 300);
    events.untilJobEnds().report(r, "masked").screenshot(dir / "masked.png");
    events.key("S").move(kCentreX, kCentreY).key("H", {"ctrl"}).report(r, "drilled").screenshot(dir / "drilled.png");
    events.key("Z", {"ctrl"}).report(r, "undone");
    events.key("Z", {"ctrl", "shift"}).report(r, "redone");
    const CommandResult run =
        play(dir, events, (dir / "shell.vdb").string(), "--stroke-log " + shellQuoted(dir / "strokes.json"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Reports reports(r);
    EXPECT_EQ(reports["start"]["shells"], 2);
    EXPECT_EQ(reports["masked"]["undo"], 1);
    EXPECT_NE(reports["masked"]["mask_checksum"], reports["start"]["mask_checksum"]);
    EXPECT_EQ(reports["masked"]["checksum"], reports["start"]["checksum"]) << "a mask moves no clay";
    EXPECT_EQ(reports["drilled"]["undo"], 2);
    EXPECT_EQ(reports["drilled"]["shells"], 1) << "the hole joins the hollow to the outside";
    EXPECT_EQ(reports["undone"]["checksum"], reports["masked"]["checksum"]);
    EXPECT_EQ(reports["redone"]["checksum"], reports["drilled"]["checksum"]);
    expectApplyGives(dir, "shell.vdb", reports["drilled"]["checksum"]);
}

TEST(SculptUi, FiltersLandAsOneUndoStepEachWithTheGridTheCommandLineWrites)
{
    TempDir dir;
    ASSERT_EQ(runSculpt("new -o clay.vdb", dir.path()).exitCode, 0);
    ASSERT_EQ(runSculpt("smooth clay.vdb --iterations 8 -o cli.vdb", dir.path()).exitCode, 0);
    const fs::path r = dir / "r.jsonl";
    UiEvents events;
    events.report(r, "start").key("S", {"alt"}).text("8").key("Enter").untilJobEnds().report(r, "smoothed");
    events.key("O", {"alt"}).text("2").key("Enter").untilJobEnds().report(r, "offset");
    events.key("Z", {"ctrl"})
        .report(r, "undo-offset")
        .key("Z", {"ctrl"})
        .report(r, "undo-smooth")
        .key("Z", {"ctrl", "shift"})
        .report(r, "redo-smooth");
    const CommandResult run = play(dir, events, (dir / "clay.vdb").string());
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Reports reports(r);
    ASSERT_EQ(reports.size(), 6u);
    EXPECT_EQ(reports["smoothed"]["last_job"], "finished") << reports["smoothed"]["error"];
    EXPECT_EQ(reports["smoothed"]["undo"], 1);
    EXPECT_EQ(reports["smoothed"]["checksum"], checksumOfFile(dir / "cli.vdb"));  // as `sculpt smooth` does it
    EXPECT_TRUE(reports["smoothed"]["modified"].get<bool>());
    EXPECT_EQ(reports["offset"]["undo"], 2);
    EXPECT_GT(reports["offset"]["volume"].get<double>(),
              1.1 * reports["smoothed"]["volume"].get<double>());  // offset by 2
    EXPECT_EQ(reports["undo-offset"]["checksum"],
              reports["smoothed"]["checksum"]);  // each undo is one filter, bit for bit
    EXPECT_EQ(reports["undo-smooth"]["checksum"], reports["start"]["checksum"]);
    EXPECT_FALSE(reports["undo-smooth"]["modified"].get<bool>());
    EXPECT_EQ(reports["redo-smooth"]["checksum"], reports["smoothed"]["checksum"]);
}

TEST(SculptUi, AMorphRunsAsAJobItsFramesPlayAndExportAsTheCommandLinesAndAKeptFrameIsOneUndoStep)
{
    TempDir dir;
    ASSERT_EQ(runSculpt("new --radius 10 --voxel-size 0.5 -o ball.vdb", dir.path()).exitCode, 0);
    ASSERT_EQ(
        runSculpt("new --shape torus --radius 9 --minor-radius 3.5 --voxel-size 0.5 -o torus.vdb", dir.path()).exitCode,
        0);
    ASSERT_EQ(runSculpt("morph ball.vdb torus.vdb -o cli", dir.path()).exitCode, 0);  // 10 frames
    const fs::path r = dir / "r.jsonl";
    UiEvents events;
    events.report(r, "start").screenshot(dir / "ball.png").key("M", {"alt"}).text("torus.vdb").key("Enter");
    events.untilJobEnds().report(r, "frames");
    for (int i = 0; i < 9; ++i) events.key("PageUp");
    events.report(r, "first-frame").key("PageDown").key("PageDown").key("PageDown").screenshot(dir / "frame3.png");
    events.key("Space").untilJobEnds().report(r, "played");  // plays to the last frame at 8 frames a second
    events.key("E", {"shift"}).key("Enter").key("K").report(r, "kept").key("Z", {"ctrl"}).report(r, "kept-undone");
    const CommandResult run = play(dir, events, (dir / "ball.vdb").string());
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Reports reports(r);
    ASSERT_EQ(reports.size(), 6u);
    const std::string original = reports["start"]["checksum"];
    EXPECT_EQ(reports["frames"]["last_job"], "finished") << reports["frames"]["error"];
    ASSERT_TRUE(reports["frames"]["morph"].is_object());
    EXPECT_EQ(reports["frames"]["morph"]["frames"], 10);
    EXPECT_EQ(reports["frames"]["morph"]["shown"], 9);
    EXPECT_TRUE(reports["frames"]["morph"]["converged"].get<bool>());
    EXPECT_EQ(reports["frames"]["morph"]["checksum"], checksumOfFile(dir / "cli" / "frame_0009.vdb"));
    EXPECT_EQ(reports["frames"]["checksum"], original);   // frames on show, the document unchanged
    EXPECT_EQ(reports["frames"]["target"], "torus.vdb");  // the target, shown as a ghost over the frames
    EXPECT_GT(reports["frames"]["ghost_triangles"].get<int>(), 500);
    EXPECT_EQ(reports["first-frame"]["morph"]["shown"], 0);
    EXPECT_EQ(reports["first-frame"]["morph"]["checksum"], checksumOfFile(dir / "cli" / "frame_0000.vdb"));
    EXPECT_GT(differingShare(readPng(dir / "ball.png"), readPng(dir / "frame3.png")), 0.005);
    EXPECT_EQ(reports["played"]["morph"]["shown"], 9);
    for (const char* frame : {"frame_0000.vdb", "frame_0004.vdb", "frame_0009.vdb"}) {
        EXPECT_EQ(checksumOfFile(dir / "morph" / frame), checksumOfFile(dir / "cli" / frame)) << frame;
    }
    EXPECT_TRUE(reports["kept"]["morph"].is_null());
    EXPECT_EQ(reports["kept"]["checksum"], checksumOfFile(dir / "cli" / "frame_0009.vdb"));
    EXPECT_EQ(reports["kept"]["undo"], 1);
    EXPECT_EQ(reports["kept"]["euler"], 0);  // the torus
    EXPECT_EQ(reports["kept-undone"]["checksum"], original);
}

// A tracked morph (Ctrl+T in Morph To): the tracked mesh is drawn as a wireframe over each frame,
// its quality is reported per frame, and Export Frames writes it beside the frames, byte for byte
// what `sculpt morph --tracked` writes.
TEST(SculptUi, ATrackedMorphShowsItsMeshOverTheFramesAndExportsItAsTheCommandLineDoes)
{
    TempDir dir;
    ASSERT_EQ(runSculpt("new --radius 10 --voxel-size 0.5 -o ball.vdb", dir.path()).exitCode, 0);
    ASSERT_EQ(runSculpt("new --shape box --radius 8 --voxel-size 0.5 -o box.vdb", dir.path()).exitCode, 0);
    ASSERT_EQ(runSculpt("morph ball.vdb box.vdb -o cli --tracked cli-tracked", dir.path()).exitCode, 0);
    const fs::path r = dir / "r.jsonl";
    UiEvents events;
    events.key("M", {"alt"}).text("box.vdb").key("T", {"ctrl"}).key("Enter").untilJobEnds().report(r, "frames");
    events.screenshot(dir / "wire.png").key("PageUp").key("PageUp").report(r, "frame7");
    events.key("E", {"shift"}).key("Enter").report(r, "exported");
    const CommandResult run = play(dir, events, (dir / "ball.vdb").string());
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Reports reports(r);
    ASSERT_EQ(reports.size(), 3u);
    EXPECT_EQ(reports["frames"]["last_job"], "finished") << reports["frames"]["error"];
    const nlohmann::json& tracked = reports["frames"]["morph"]["tracked"];
    ASSERT_TRUE(tracked.is_object()) << reports["frames"]["morph"];
    ASSERT_EQ(tracked["frames"].size(), 10u);  // the frames the dialog and the command line default to
    std::size_t segment = 0;
    for (const nlohmann::json& frame : tracked["frames"]) {
        EXPECT_GT(frame["vertices"].get<int>(), 500);
        EXPECT_GT(frame["smallest_angle"].get<double>(), 10.0);
        EXPECT_EQ(frame["flagged"], 0);
        EXPECT_GE(frame["segment"].get<std::size_t>(), segment);  // segments follow each other
        segment = frame["segment"].get<std::size_t>();
    }
    EXPECT_EQ(tracked["segments"].get<std::size_t>(), segment + 1);
    EXPECT_TRUE(tracked["wire_shown"].get<bool>());
    EXPECT_EQ(tracked["wire_frame"], 9);  // the last frame, shown first
    EXPECT_EQ(reports["frame7"]["morph"]["tracked"]["wire_frame"], 7);
    EXPECT_EQ(reports["exported"]["checksum"], reports["frames"]["checksum"]);  // the document unchanged
    std::size_t files = 0;  // every file the command line wrote, byte for byte
    for (const auto& entry : fs::directory_iterator(dir / "cli-tracked")) {
        EXPECT_EQ(fileBytes(dir / "morph" / "tracked" / entry.path().filename()), fileBytes(entry.path()))
            << entry.path().filename();
        ++files;
    }
    EXPECT_EQ(files, 4 * (segment + 1) + 1);  // .ply, .pc2, .glb and .usda per segment, and segments.json
}

TEST(SculptUi, AMorphCancelledHalfWayLeavesTheDocumentAsItWas)
{
    TempDir dir;
    ASSERT_EQ(runSculpt("new -o clay.vdb", dir.path()).exitCode, 0);
    ASSERT_EQ(runSculpt("new --shape box --radius 36 -o box.vdb", dir.path()).exitCode, 0);
    const fs::path r = dir / "r.jsonl";
    UiEvents events;
    events.report(r, "start").key("M", {"alt"}).text("box.vdb").key("Enter").wait(1.0).report(r, "running");
    events.key("Escape").untilJobEnds().report(r, "cancelled");
    const CommandResult run = play(dir, events, (dir / "clay.vdb").string());
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Reports reports(r);
    ASSERT_EQ(reports.size(), 3u);
    ASSERT_TRUE(reports["running"]["job"].is_object()) << "the morph cannot be over in a second";
    EXPECT_EQ(reports["running"]["job"]["label"], "morph to box.vdb");
    EXPECT_EQ(reports["cancelled"]["last_job"], "cancelled");
    EXPECT_TRUE(reports["cancelled"]["morph"].is_null());
    EXPECT_EQ(reports["cancelled"]["checksum"], reports["start"]["checksum"]);
    EXPECT_EQ(reports["cancelled"]["undo"], 0);
}

TEST(SculptUi, TheScalesViewDrawsDiscsWhereTheSurfaceIsWithFarFewerPrimitives)
{
    TempDir dir;
    const fs::path r = dir / "r.jsonl";
    UiEvents events;
    events.screenshot(dir / "plain.png").key("V").screenshot(dir / "scales.png").report(r, "scales");
    events.key("V").screenshot(dir / "back.png");
    const CommandResult run = play(dir, events);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Reports reports(r);
    ASSERT_EQ(reports.size(), 1u);
    const double scales = reports["scales"]["scales"].get<double>(),
                 triangles = reports["scales"]["triangles"].get<double>();
    // A scale per 3-voxel cell the clay ball's surface passes through (area 31,416, cells of 1.5):
    // a surface of area A meets about 1.5 A / c^2 cubic cells of side c, here 20,944.
    const double expected = 1.5 * 31416.0 / (1.5 * 1.5);
    EXPECT_NEAR(scales, expected, 0.25 * expected);
    EXPECT_LT(6.0 * scales, 0.4 * triangles);  // hexagons: a third of the mesh's triangles
    const auto plain = readPng(dir / "plain.png"), scaled = readPng(dir / "scales.png");
    EXPECT_GT(differingShare(plain, scaled), 0.01);                      // a different picture
    EXPECT_LT(differingShare(plain, readPng(dir / "back.png")), 0.005);  // and back (the status text varies)
}

/// Distance from `p` to the polyline through `points`.
double distanceToPolyline(const openvdb::Vec3d& p, const std::vector<openvdb::Vec3d>& points)
{
    double best = (p - points.front()).length();
    for (std::size_t i = 1; i < points.size(); ++i) {
        const openvdb::Vec3d a = points[i - 1], ab = points[i] - a;
        const double t = ab.lengthSqr() > 0.0 ? std::clamp((p - a).dot(ab) / ab.lengthSqr(), 0.0, 1.0) : 0.0;
        best = std::min(best, (p - (a + ab * t)).length());
    }
    return best;
}

TEST(SculptUi, TheFollowBrushPullsTheSurfaceUnderItOntoTheTargetAndNothingElse)
{
    TempDir dir;
    ASSERT_EQ(runSculpt("new -o ball.vdb", dir.path()).exitCode, 0);                         // radius 50
    ASSERT_EQ(runSculpt("new --shape box --radius 47 -o box.vdb", dir.path()).exitCode, 0);  // 3 inside it
    const fs::path r = dir / "r.jsonl";
    UiEvents events;
    events.screenshot(dir / "plain.png").key("T", {"ctrl"}).text("box.vdb").key("Enter").untilJobEnds();
    events.report(r, "target").screenshot(dir / "ghost.png").key("H").screenshot(dir / "hidden.png").key("H");
    events.key("O").drag(600, 400, 690, 410, 30).drag(690, 380, 600, 390, 30).report(r, "followed");
    events.key("Z", {"ctrl"}).key("Z", {"ctrl"}).report(r, "undone");
    const CommandResult run =
        play(dir, events, (dir / "ball.vdb").string(),
             "--stroke-log " + shellQuoted(dir / "strokes.json") + " --save-as " + shellQuoted(dir / "undone.vdb"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Reports reports(r);
    ASSERT_EQ(reports.size(), 3u);
    EXPECT_EQ(reports["target"]["target"], "box.vdb") << reports["target"]["error"];
    EXPECT_GT(reports["target"]["ghost_triangles"].get<int>(), 1000);
    const auto plain = readPng(dir / "plain.png"), ghost = readPng(dir / "ghost.png");
    EXPECT_GT(differingShare(plain, ghost), 0.05);                         // the ghost is drawn over the ball
    EXPECT_LT(differingShare(plain, readPng(dir / "hidden.png")), 0.005);  // H hides it
    EXPECT_EQ(reports["followed"]["undo"], 2);
    EXPECT_EQ(reports["undone"]["checksum"], reports["target"]["checksum"]);  // undo restores the grid bit for bit
    EXPECT_EQ(checksumOfFile(dir / "undone.vdb"), reports["target"]["checksum"]);

    // The two strokes again, by `sculpt apply` of the log the window wrote (it names box.vdb),
    // without its undos.
    std::ifstream logFile(dir / "strokes.json");
    nlohmann::json log = nlohmann::json::parse(logFile);
    auto& logged = log["events"];
    logged.erase(std::remove_if(logged.begin(), logged.end(), [](const auto& e) { return e.contains("action"); }),
                 logged.end());
    std::ofstream(dir / "strokes_only.json") << log.dump();
    const CommandResult apply = runSculpt("apply ball.vdb strokes_only.json -o followed.vdb", dir.path());
    ASSERT_EQ(apply.exitCode, 0) << apply.err;
    const FieldImage before = readFieldImage(dir / "ball.vdb"), after = readFieldImage(dir / "followed.vdb");
    const FieldImage box = readFieldImage(dir / "box.vdb");
    std::vector<openvdb::Vec3d> path;
    double radius = 0.0;
    for (const auto& event : log["events"]) {
        if (!event.contains("tool")) continue;
        EXPECT_EQ(event["tool"], "follow");
        radius = event["radius"];
        for (const auto& sample : event["samples"]) {
            path.emplace_back(sample["position"][0], sample["position"][1], sample["position"][2]);
        }
    }
    ASSERT_GT(path.size(), 10u);
    // Every voxel that changed lies under the brush; near the surface under it, the distance
    // to the box fell.
    const auto& xform = before.grid().transform();
    const auto a = before.grid().getConstAccessor(), b = after.grid().getConstAccessor();
    const auto boxAcc = box.grid().getConstAccessor();
    std::size_t changed = 0, outside = 0;
    double distanceBefore = 0.0, distanceAfter = 0.0;
    int nearBefore = 0, nearAfter = 0;
    for (auto leaf = after.grid().tree().cbeginLeaf(); leaf; ++leaf) {
        for (auto it = leaf->cbeginValueAll(); it; ++it) {
            const openvdb::Coord ijk = it.getCoord();
            const openvdb::Vec3d p = xform.indexToWorld(ijk);
            const double reach = distanceToPolyline(p, path);
            if (a.getValue(ijk) != b.getValue(ijk) || a.isValueOn(ijk) != b.isValueOn(ijk)) {
                ++changed;
                if (reach > radius + 1e-6) ++outside;
            }
            if (reach > 0.5 * radius) continue;
            const double boxPhi = std::abs(boxAcc.getValue(box.grid().transform().worldToIndexCellCentered(p)));
            if (std::abs(a.getValue(ijk)) < 0.5) distanceBefore += boxPhi, ++nearBefore;
            if (std::abs(b.getValue(ijk)) < 0.5) distanceAfter += boxPhi, ++nearAfter;
        }
    }
    EXPECT_GT(changed, 1000u);
    EXPECT_EQ(outside, 0u) << "of " << changed << " changed voxels";
    ASSERT_GT(nearBefore, 100);
    ASSERT_GT(nearAfter, 100);
    EXPECT_LT(distanceAfter / nearAfter, 0.6 * distanceBefore / nearBefore)
        << "mean distance to the box under the brush: " << distanceBefore / nearBefore << " before";
}

TEST(SculptUi, TheImportPanelPreviewsTheIsoValueLiveAndAppliesTheGridTheCommandLineImports)
{
    const char* mri = "/usr/share/mricron/templates/ch2bet.nii.gz";
    if (!fs::exists(mri)) GTEST_SKIP() << mri << " missing: apt-get install mricron-data";
    TempDir dir;
    ASSERT_EQ(runSculpt(std::string("import ") + mri + " --largest-component -o cli.vdb", dir.path()).exitCode, 0);
    const fs::path r = dir / "r.jsonl";
    UiEvents events;
    events.report(r, "start").key("I", {"ctrl"}).text(mri).key("Enter").untilJobEnds();
    events.report(r, "otsu").screenshot(dir / "otsu.png");
    for (int i = 0; i < 8; ++i) events.key("PageUp");
    events.wait(0.3).report(r, "higher").screenshot(dir / "higher.png");
    events.key("Escape").report(r, "cancelled");  // cancelled: nothing changed
    events.key("I", {"ctrl"}).text(mri).key("Enter").untilJobEnds().key("Enter").untilJobEnds();
    events.wait(0.3).report(r, "applied");
    // A preview budget far under the scan's mesh: the applied import shows a coarse preview first.
    const CommandResult run = play(dir, events, "", "--preview-triangles 20000");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Reports reports(r);
    ASSERT_EQ(reports.size(), 5u);
    const std::string original = reports["start"]["checksum"];
    ASSERT_EQ(reports["otsu"]["mode"], "import") << reports["otsu"]["error"];
    EXPECT_EQ(reports["otsu"]["import"]["iso"], reports["otsu"]["import"]["otsu"]);  // Otsu's by default
    EXPECT_GT(reports["otsu"]["import"]["preview_triangles"].get<int>(), 10000);
    EXPECT_EQ(reports["otsu"]["checksum"], original);
    // Eight steps up by 1% of the range; the preview follows, the document does not.
    EXPECT_GT(reports["higher"]["import"]["iso"].get<double>(), reports["otsu"]["import"]["iso"].get<double>());
    EXPECT_EQ(reports["higher"]["checksum"], original);
    EXPECT_FALSE(reports["higher"]["preview_latencies_ms"].empty());
    EXPECT_GT(differingShare(readPng(dir / "otsu.png"), readPng(dir / "higher.png")), 0.01);
    EXPECT_TRUE(reports["cancelled"]["mode"].is_null()) << "the import panel closed";
    EXPECT_EQ(reports["cancelled"]["checksum"], original);
    EXPECT_EQ(reports["applied"]["last_job"], "finished") << reports["applied"]["error"];
    EXPECT_EQ(reports["applied"]["checksum"], checksumOfFile(dir / "cli.vdb"));  // Otsu, largest piece, 1 mm
    EXPECT_EQ(reports["applied"]["shells"], 1);
    EXPECT_EQ(reports["start"]["previews_shown"], 0);
    EXPECT_EQ(reports["applied"]["previews_shown"], 1);
    EXPECT_EQ(reports["applied"]["display_pending_chunks"], 0);  // then full detail everywhere
    EXPECT_EQ(reports["applied"]["triangles_drawn"], reports["applied"]["triangles"]);
}

TEST(SculptUi, PrimitivesPlacedInThePanelBakeToTheGridSculptBuildMakesOfTheSceneItSaves)
{
    TempDir dir;
    ASSERT_EQ(runSculpt("new -o ball.vdb", dir.path()).exitCode, 0);
    const fs::path r = dir / "r.jsonl";
    UiEvents events;
    events.report(r, "start").screenshot(dir / "plain.png");
    events.move(600, 380).key("A", {"shift"}).move(700, 420).key("A", {"shift"});
    events.drag(700, 420, 660, 300, 10).screenshot(dir / "xray.png").report(r, "placed");  // the second one dragged up
    events.key("Z", {"alt"}).screenshot(dir / "opaque.png").key("Z", {"alt"});
    events.key("S", {"ctrl", "alt"}).text("scene.json").key("Enter");
    events.key("Enter").untilJobEnds().report(r, "baked").key("Z", {"ctrl"}).report(r, "bake-undone");
    const CommandResult run = play(dir, events, (dir / "ball.vdb").string());
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Reports reports(r);
    ASSERT_EQ(reports.size(), 4u);
    ASSERT_TRUE(reports["placed"].contains("primitives")) << reports["placed"]["error"];
    EXPECT_EQ(reports["placed"]["primitives"]["count"], 2);
    EXPECT_GT(reports["placed"]["primitives"]["preview_triangles"].get<int>(), 1000);
    EXPECT_TRUE(reports["placed"]["xray"].get<bool>());
    EXPECT_EQ(reports["placed"]["checksum"], reports["start"]["checksum"]);  // nothing baked yet
    const auto plain = readPng(dir / "plain.png"), xray = readPng(dir / "xray.png");
    EXPECT_GT(differingShare(plain, xray), 0.1);                        // the see-through clay
    EXPECT_GT(differingShare(xray, readPng(dir / "opaque.png")), 0.1);  // Alt+Z makes it opaque again

    std::ifstream sceneFile(dir / "scene.json");
    ASSERT_TRUE(sceneFile) << "the scene was not saved";
    const nlohmann::json scene = nlohmann::json::parse(sceneFile);
    ASSERT_EQ(scene["primitives"].size(), 2u);
    EXPECT_GT(scene["primitives"][1]["skeleton"]["position"][1].get<double>(),
              scene["primitives"][0]["skeleton"]["position"][1].get<double>() + 5.0);  // dragged up

    const CommandResult build = runSculpt("build scene.json --into ball.vdb -o cli.vdb", dir.path());
    ASSERT_EQ(build.exitCode, 0) << build.err;
    EXPECT_EQ(reports["baked"]["last_job"], "finished") << reports["baked"]["error"];
    EXPECT_EQ(reports["baked"]["checksum"], checksumOfFile(dir / "cli.vdb"));
    EXPECT_GT(reports["baked"]["volume"].get<double>(), reports["start"]["volume"].get<double>() + 100.0);
    EXPECT_EQ(reports["baked"]["undo"], 1);
    EXPECT_EQ(reports["bake-undone"]["checksum"], reports["start"]["checksum"]);
}

mode_t modeOf(const fs::path& path)
{
    struct stat s {};
    return stat(path.c_str(), &s) == 0 ? s.st_mode & 07777 : 0;
}

TEST(SculptUi, ImportingASliceThatMakesGdcmAbortShowsAnErrorAndTheSessionAndDocumentLiveOn)
{
    TempDir dir;
    fs::copy(SCULPT_TESTS_DIR "/bad-inputs/dicom_gdcm_abort", dir / "abort");
    const fs::path r = dir / "r.jsonl";
    UiEvents events;
    events.drag(560, 380, 700, 380).report(r, "stroke");  // unsaved work
    events.key("I", {"ctrl"}).text((dir / "abort").string()).key("Enter").untilJobEnds().report(r, "refused");
    events.key("Enter");                                        // dismisses the error
    events.drag(560, 420, 700, 420).report(r, "sculpting-on");  // and sculpting goes on
    const mode_t saved = umask(0);  // the widest: the state must be private whatever the user's umask
    const CommandResult run = play(dir, events);
    umask(saved);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Reports reports(r);
    ASSERT_EQ(reports.size(), 3u);
    EXPECT_NE(reports["refused"]["error"].get<std::string>().find("slice_2.dcm: the DICOM reader failed on this file"),
              std::string::npos)
        << reports["refused"].dump();
    EXPECT_EQ(reports["refused"]["checksum"], reports["stroke"]["checksum"]);
    EXPECT_TRUE(reports["refused"]["modified"].get<bool>());
    EXPECT_NE(reports["sculpting-on"]["checksum"], reports["refused"]["checksum"]);
    // The work was autosaved before the file was read (the clean quit then removed the copy;
    // its mode is ui_unit_tests' Autosave case); the state is the user's alone.
    EXPECT_NE(run.out.find("sculpt-ui: autosaved to " + (dir / "state" / "recovery").string()), std::string::npos)
        << run.out;
    EXPECT_EQ(modeOf(dir / "state"), 0700u);
    EXPECT_EQ(modeOf(dir / "state" / "recovery"), 0700u);
}

TEST(SculptUi, BadInputIsOneLineAndExitTwo)
{
    TempDir dir;
    std::ofstream(dir / "bad.json") << R"({"events": [{"type": "fly"}]})";
    const CommandResult run = runUi("--play bad.json --state-dir state", dir.path().string());
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.err.find("bad.json: events[0]: field 'type' is \"fly\""), std::string::npos) << run.err;
    std::ofstream(dir / "corrupt.vdb") << "garbage";
    const CommandResult open = runUi("corrupt.vdb --screenshot x.png --state-dir state", dir.path().string());
    EXPECT_EQ(open.exitCode, 2);
    EXPECT_NE(open.err.find("corrupt.vdb"), std::string::npos) << open.err;
    EXPECT_FALSE(fs::exists(dir / "x.png"));
}

// The window without a display (sculpt-ui --headless, the same app on a window that draws
// nothing) replays a stroke, a lasso cut, a box mask and an undo to the grids the window under
// Xvfb makes, bit for bit: the headless tests (ui_unit_tests) stand for the window.
TEST(SculptUi, AHeadlessReplayGivesTheWindowsGridsBitForBit)
{
    TempDir dir;
    UiEvents events;
    const auto stages = [&events](const fs::path& r) {
        events.untilJobEnds().move(560, 380).drag(560, 380, 720, 400).report(r, "stroke");
        events.key("J").move(kCentreX + 450, kCentreY).press().ellipse(kCentreX + 250, kCentreY, 200, 140);
        events.release().untilJobEnds().report(r, "cut");
        events.key("B", {"shift"}).drag(kCentreX - 380, kCentreY - 300, kCentreX - 120, kCentreY + 300);
        events.untilJobEnds().report(r, "masked").key("Z", {"ctrl"}).report(r, "undone");
    };
    stages(dir / "window.jsonl");
    ASSERT_EQ(play(dir, events).exitCode, 0);
    events = UiEvents();
    stages(dir / "headless.jsonl");
    events.write(dir / "headless.json");
    const CommandResult headless =
        runCommand("'" SCULPT_UI_EXECUTABLE "' --headless --play headless.json --state-dir state", dir.path().string());
    ASSERT_EQ(headless.exitCode, 0) << headless.err;
    const Reports window(dir / "window.jsonl"), alone(dir / "headless.jsonl");
    for (const char* stage : {"stroke", "cut", "masked", "undone"}) {
        EXPECT_EQ(alone[stage]["checksum"], window[stage]["checksum"]) << stage;
        EXPECT_EQ(alone[stage]["mask_checksum"], window[stage]["mask_checksum"]) << stage;
        EXPECT_EQ(alone[stage]["undo"], window[stage]["undo"]) << stage;
    }
    EXPECT_NE(window["cut"]["checksum"], window["stroke"]["checksum"]);
    EXPECT_NE(window["masked"]["mask_checksum"], "");
    const CommandResult screenshot = runCommand("'" SCULPT_UI_EXECUTABLE "' --headless --play headless.json "
                                                "--screenshot x.png",
                                                dir.path().string());
    EXPECT_EQ(screenshot.exitCode, 2) << "nothing is drawn headless: no screenshot";
}

// A DISPLAY that names no usable X server: sculpt-ui says so in one line and exits 2, and the
// README's first command (scripts/demo.sh) goes headless instead of stopping there.
TEST(SculptUi, AnUnusableDisplayIsExitTwoAndTheDemoFallsBackToItsHeadlessRun)
{
    TempDir dir;
    const std::string unusable = "DISPLAY=nowhere.invalid:0 ";  // no such host: never a server
    const CommandResult run = runCommand(unusable + "'" SCULPT_UI_EXECUTABLE "'", dir.path().string());
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_NE(run.err.find("cannot open a window"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("DISPLAY=nowhere.invalid:0"), std::string::npos) << run.err;

    const CommandResult demo =
        runCommand(unusable + "SCULPT_DEMO_BUILD='" SCULPT_BUILD_DIR "' SCULPT_DEMO_OUT=" + shellQuoted(dir / "out") +
                       " bash '" SCULPT_SOURCE_DIR "/scripts/demo.sh'",
                   dir.path().string());
    ASSERT_EQ(demo.exitCode, 0) << demo.out << demo.err;
    EXPECT_NE(demo.out.find("runs headless under Xvfb instead"), std::string::npos) << demo.out;
    for (const char* file : {"face.vdb", "face.ply", "face-ui.png", "clay-ui.png", "face.png"})
        EXPECT_GT(fs::file_size(dir / "out" / file), 0u) << file;
}

}  // namespace
}  // namespace sculpt::test

namespace sculpt::test {
namespace {

/// A body (edited), an eye on another lattice and a hat placed above it, apart from the body.
std::vector<Piece> bodyEyeAndHat()
{
    std::vector<Piece> pieces{{{"body"}, makeSphere(20.0, 0.5)},
                              {{"eye", {0.1f, 0.3f, 0.9f}}, makeSphere(3.0, 0.25)},
                              {{"hat", {0.9f, 0.2f, 0.2f}}, makeBox(6.0, 0.5)}};
    pieces[1].placement.setTranslation(openvdb::Vec3d(8.0, 8.0, 18.0));
    pieces[2].placement.setTranslation(openvdb::Vec3d(0.0, 30.0, 0.0));
    return pieces;
}

// A document of three pieces opens with the first to sculpt and the others drawn in their colours
// where they are placed; a stroke on the first leaves the others bit for bit, and saving keeps
// every piece, its look and its placement.
TEST(SculptUi, TheOtherPiecesAreDrawnAndAStrokeOnOneLeavesThemBitForBit)
{
    TempDir dir;
    const std::vector<Piece> pieces = bodyEyeAndHat();
    writeVdbPieces(pieces, dir / "figure.vdb");
    const fs::path r = dir / "r.jsonl";
    UiEvents events;
    events.report(r, "opened").screenshot(dir / "figure.png").drag(560, 420, 700, 380, 30).report(r, "stroked");
    const CommandResult run =
        play(dir, events, (dir / "figure.vdb").string(), "--save-as " + shellQuoted(dir / "saved.vdb"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Reports reports(r);
    EXPECT_EQ(reports["opened"]["other_pieces"], 2);
    EXPECT_GT(reports["opened"]["other_pieces_triangles"].get<int>(), 1000);
    EXPECT_NE(reports["stroked"]["checksum"], reports["opened"]["checksum"]) << "the stroke changed the body";
    const VdbPieces saved = readVdbPieces(dir / "saved.vdb");
    ASSERT_EQ(saved.pieces.size(), 3u);
    EXPECT_EQ(formatChecksum(gridChecksum(saved.pieces[0].field.grid())), reports["stroked"]["checksum"]);
    for (std::size_t i = 1; i < 3; ++i) {
        EXPECT_EQ(saved.pieces[i].name, pieces[i].name);
        EXPECT_EQ(gridChecksum(saved.pieces[i].field.grid()), gridChecksum(pieces[i].field.grid())) << pieces[i].name;
        EXPECT_EQ(saved.pieces[i].colour, pieces[i].colour);
        EXPECT_EQ(saved.pieces[i].placement, pieces[i].placement);
    }
}

// In pieces mode (Tab) G moves the sculpted piece by a typed value along X: moved and moved
// back, no voxel changed and the placement is where it was; a move into the other piece stops
// at contact; with push on (P) the other is dented as a job, keeping its volume, and the move and
// the dent are one undo step; smoothing the moved piece leaves the other bit for bit; applying
// the move resamples it where it stands; the export writes a file per piece, each where it is.
TEST(SculptUi, PiecesMoveStopAtContactPushAsOneUndoStepAndExportEach)
{
    TempDir dir;
    const std::vector<Piece> pieces = bodyAndBallApart();  // body to x = 10, ball from 24
    writeVdbPieces(pieces, dir / "two.vdb");
    const fs::path r = dir / "r.jsonl";
    UiEvents events;
    const auto moveX = [&events](std::vector<std::string> typed) {
        events.key("G").key("X");
        for (const std::string& key : typed) events.key(key);
        events.key("Enter");
    };
    events.untilJobEnds().report(r, "opened").key("Tab");
    moveX({"5"});
    events.report(r, "moved");
    moveX({"Minus", "5"});
    events.report(r, "back");
    moveX({"2", "0"});
    events.report(r, "stopped").key("P");
    moveX({"2"});
    events.untilJobEnds().report(r, "pushed").screenshot(dir / "pushed.png");
    events.key("Z", {"ctrl"}).report(r, "undone").key("Z", {"ctrl", "shift"}).report(r, "redone");
    events.key("Tab").key("S", {"alt"}).text("4").key("Enter").untilJobEnds().report(r, "smoothed");
    events.key("Tab").key("A", {"ctrl"}).untilJobEnds().report(r, "applied");
    const CommandResult run =
        play(dir, events, (dir / "two.vdb").string(),
             "--save-as " + shellQuoted(dir / "saved.vdb") + " --export " + shellQuoted(dir / "out.ply"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Reports reports(r);
    const auto piece = [&reports](const std::string& name, int i) { return reports[name]["pieces"][i]; };
    const std::string body = piece("opened", 0)["checksum"], ball = piece("opened", 1)["checksum"];
    EXPECT_DOUBLE_EQ(placedX(piece("moved", 0)), 5.0);
    EXPECT_EQ(placedX(piece("back", 0)), 0.0);
    EXPECT_EQ(piece("back", 0)["placement"], piece("opened", 0)["placement"]);
    for (const char* name : {"moved", "back", "stopped"}) {
        EXPECT_EQ(piece(name, 0)["checksum"], body) << name << ": a move changes no voxel";
        EXPECT_EQ(piece(name, 1)["checksum"], ball) << name;
    }
    // Stopped where the body's surface (x = 10 + t) meets the ball's (x = 24): within half a voxel.
    const double stopped = placedX(piece("stopped", 0));
    EXPECT_GT(stopped, 14.0 - 0.25);
    EXPECT_LE(stopped, 14.0 + 0.01);
    EXPECT_NEAR(placedX(piece("pushed", 0)), stopped + 2.0, 1e-9);
    EXPECT_EQ(piece("pushed", 0)["checksum"], body);
    EXPECT_NE(piece("pushed", 1)["checksum"], ball) << "the ball was dented";
    EXPECT_EQ(reports["pushed"]["undo"].get<int>(), reports["stopped"]["undo"].get<int>() + 1);
    EXPECT_EQ(piece("undone", 1)["checksum"], ball) << "one undo step takes back the dent...";
    EXPECT_EQ(placedX(piece("undone", 0)), stopped) << "... and the move";
    EXPECT_EQ(piece("redone", 1)["checksum"], piece("pushed", 1)["checksum"]);
    EXPECT_NE(piece("smoothed", 0)["checksum"], body) << "smoothing changed the body: " << reports["smoothed"].dump();
    EXPECT_EQ(piece("smoothed", 1)["checksum"], piece("redone", 1)["checksum"]) << "and left the ball bit for bit";

    const VdbPieces saved = readVdbPieces(dir / "saved.vdb");
    ASSERT_EQ(saved.pieces.size(), 2u);
    const double before = openvdb::tools::levelSetVolume(pieces[1].field.grid()),
                 after = openvdb::tools::levelSetVolume(saved.pieces[1].field.grid());
    EXPECT_NEAR(after, before, 0.005 * before) << "the dented ball keeps its volume";
    // Apply Move (Ctrl+A) resampled the body where it stood: no placement left, the same surface.
    EXPECT_EQ(saved.pieces[0].placement, openvdb::Mat4d::identity());
    EXPECT_EQ(reports["applied"]["undo"].get<int>(), reports["smoothed"]["undo"].get<int>() + 1);
    EXPECT_NEAR(reports["applied"]["volume"].get<double>(), reports["smoothed"]["volume"].get<double>(),
                0.01 * reports["smoothed"]["volume"].get<double>());
    EXPECT_EQ(piece("applied", 1)["checksum"], piece("smoothed", 1)["checksum"]);
    // A file per piece, where each is placed: the ball's mesh starts beyond the body's.
    ASSERT_TRUE(fs::exists(dir / "out-body.ply")) << run.out << run.err;
    const TriangleMesh bodyMesh = readMesh(dir / "out-body.ply"), ballMesh = readMesh(dir / "out-ball.ply");
    float bodyMax = -1e9f, ballMin = 1e9f;
    for (const auto& p : bodyMesh.positions) bodyMax = std::max(bodyMax, p[0]);
    for (const auto& p : ballMesh.positions) ballMin = std::min(ballMin, p[0]);
    EXPECT_NEAR(bodyMax, 10.0 + stopped + 2.0, 0.5);
    EXPECT_GT(ballMin, 20.0);
}

}  // namespace
}  // namespace sculpt::test
