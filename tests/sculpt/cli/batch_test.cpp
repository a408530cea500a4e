// SPDX-License-Identifier: Apache-2.0
// The program as a batch job runs it: interrupted by Ctrl-C or a scheduler, under a memory limit,
// its reports read as JSON, on any number of threads.

#include "tests/support/file_bytes.h"
#include "tests/support/run_sculpt.h"
#include "tests/support/synthetic_scan.h"
#include "tests/support/temp_dir.h"
#include "tests/support/threemf_reader.h"

#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <map>
#include <thread>

namespace sculpt {
namespace {

using test::runSculpt;
using test::TempDir;
namespace fs = std::filesystem;

/// Files in `dir` whose names start with a dot: the writers' hidden temporaries.
std::vector<std::string> hiddenFiles(const fs::path& dir)
{
    std::vector<std::string> hidden;
    for (const std::string& name : TempDir::entriesOf(dir))
        if (name.front() == '.') hidden.push_back(name);
    return hidden;
}

// Ctrl-C in the middle of a long morph: exit 130, the frames written so far whole, no temporary.
TEST(Batch, SigintDuringAMorphLeavesNoTemporaryAndExits130)
{
    TempDir dir;
    ASSERT_EQ(runSculpt("new --radius 5 --voxel-size 0.5 -o a.vdb", dir.path()).exitCode, 0);
    ASSERT_EQ(runSculpt("new --shape box --radius 6 --voxel-size 0.5 -o b.vdb", dir.path()).exitCode, 0);
    const int pid = test::startSculpt("morph a.vdb b.vdb --frames 2000 --mesh ply -o frames", dir.path());
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (!fs::exists(dir / "frames/frame_0003.ply") && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    kill(pid, SIGINT);
    const auto r = test::finishSculpt(pid, dir.path().string());
    EXPECT_EQ(r.exitCode, 130) << r.err;
    EXPECT_EQ(r.err, "sculpt: interrupted (no partial file left)\n");
    EXPECT_EQ(hiddenFiles(dir / "frames"), std::vector<std::string>{});
    EXPECT_FALSE(fs::exists(dir / "frames/frame_1999.vdb"));  // it was stopped, not finished
}

// SIGTERM (a scheduler's time limit, `kill`) while an edit writes the document: exit 143, the
// input untouched, no temporary beside it.
TEST(Batch, SigtermDuringAnEditExits143AndLeavesTheInputAsItWas)
{
    TempDir dir;
    ASSERT_EQ(runSculpt("new --radius 30 --voxel-size 0.25 -o big.vdb", dir.path()).exitCode, 0);
    const auto before = fs::file_size(dir / "big.vdb");
    const int pid = test::startSculpt("smooth big.vdb --iterations 400 -o big.vdb", dir.path());
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));
    kill(pid, SIGTERM);
    const auto r = test::finishSculpt(pid, dir.path().string());
    EXPECT_EQ(r.exitCode, 143) << r.err;
    EXPECT_EQ(fs::file_size(dir / "big.vdb"), before);
    EXPECT_EQ(hiddenFiles(dir.path()), std::vector<std::string>{});
}

/// A fresh memory control group this test may make (run as root, with a writable v1 memory
/// hierarchy or v2 with the memory controller given to the root's children), or empty.
fs::path makeMemoryGroup(std::uint64_t limitBytes)
{
    const std::string name = "sculpt-test-" + std::to_string(getpid());
    std::error_code error;
    if (fs::exists("/sys/fs/cgroup/memory/memory.limit_in_bytes")) {
        const fs::path group = fs::path("/sys/fs/cgroup/memory") / name;
        if (fs::create_directory(group, error) && (std::ofstream(group / "memory.limit_in_bytes") << limitBytes))
            return group;
    }
    std::ifstream controllers("/sys/fs/cgroup/cgroup.subtree_control");
    std::string word;
    while (controllers >> word) {
        const fs::path group = fs::path("/sys/fs/cgroup") / name;
        if (word == "memory" && fs::create_directory(group, error) &&
            (std::ofstream(group / "memory.max") << limitBytes))
            return group;
    }
    return {};
}

// Slurm's --mem or docker --memory: a 1 GB shape under a 200 MB group is refused before any work,
// with one line naming the limit (not killed by the kernel with exit 137 and no word).
TEST(Batch, AControlGroupsMemoryLimitRefusesWhatWouldNotFit)
{
    const fs::path group = makeMemoryGroup(200u << 20);
    if (group.empty()) GTEST_SKIP() << "cannot make a memory control group here (not root, or not delegated)";
    TempDir dir;
    // The shell moves itself into the group, then becomes sculpt ("$0") there.
    const auto r = test::runCommand("sh -c 'echo $$ > " + (group / "cgroup.procs").string() +
                                        " && exec \"$0\" new --radius 115 --voxel-size 0.1 -o big.vdb' '" +
                                        test::sculptExecutable() + std::string("'"),
                                    dir.path().string());
    fs::remove(group);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("under the control group's memory limit"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "big.vdb"));
}

/// Every command, each input made by an earlier one, as a pipeline author chains them.
const std::vector<std::string> kEveryCommand{
    "new --radius 6 --voxel-size 0.5 -o a.vdb --mesh a-new.ply",
    "new --shape box --radius 5 --voxel-size 0.5 -o b.vdb",
    "info a.vdb",
    "mesh a.vdb -o a.stl",
    "smooth a.vdb --iterations 3 --keep-volume -o smooth.vdb --mesh smooth.ply",
    "offset a.vdb --distance 0.5 -o offset.vdb --mesh offset.obj",
    "hollow a.vdb --thickness 1.5 --drain -o hollow.vdb --mesh hollow.stl",
    "islands a.vdb --remove-under 1 -o islands.vdb --mesh islands.ply",
    "morph a.vdb b.vdb --frames 3 --keep-volume -o frames --mesh ply",
    "build " SCULPT_DATA_DIR "/scenes/snowman.json --voxel-size 0.5 -o snowman.vdb --mesh snowman.ply",
    "new -o clay.vdb",
    "apply clay.vdb " SCULPT_DATA_DIR "/strokes/face.json -o face.vdb --mesh face.ply",
    "import map.raw --raw-dims 48,32,32 --iso 0.5 -o scan.vdb --mesh scan.ply",
    "import a-new.ply --voxel-size 0.5 -o from-mesh.vdb",
    "import map.raw --raw-dims 48,32,32 --labels -o labels.vdb --mesh labels.obj",
    "export-labels labels.vdb -o labels.nii.gz",
    "pieces labels.vdb --rename 'label 1=box' -o renamed.vdb --mesh renamed.3mf",
    "render a.vdb -o a.png --width 64 --height 48",
    "render frames -o images --frames 1-2 --width 32 --height 24 --format exr",
};

/// Runs every command in `dir` with `options`; returns their reports, each written to a file in
/// `reports` for the validator.
std::vector<std::string> runEveryCommand(const TempDir& dir, const std::string& options, const fs::path& reports)
{
    test::writeThreeLabelRaw(dir / "map.raw");
    std::vector<std::string> files;
    for (const std::string& command : kEveryCommand) {
        const auto r = runSculpt(command + " " + options, dir.path().string());
        EXPECT_EQ(r.exitCode, 0) << command << ": " << r.err;
        files.push_back((reports / (std::to_string(files.size()) + ".json")).string());
        std::ofstream(files.back()) << r.out;
        EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << command << ": " << r.out;
    }
    return files;
}

/// Every regular file under `dir`, by path relative to it, with its bytes.
std::map<std::string, std::string> filesUnder(const fs::path& dir)
{
    std::map<std::string, std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(dir))
        if (entry.is_regular_file()) files[fs::relative(entry.path(), dir).string()] = test::fileBytes(entry.path());
    return files;
}

// A pipeline reads every command's report as JSON with stable keys (validated here by Debian's
// python3-jsonschema against data/reports.schema.json), and gets the same files whatever the
// thread count: one worker or two, bit for bit.
TEST(Batch, EveryCommandsJsonValidatesAndOneThreadOrTwoWriteTheSameFiles)
{
    TempDir one, two, reports;
    std::vector<std::string> files = runEveryCommand(one, "--json --threads 1", reports.path());
    fs::create_directory(reports / "two");
    for (const std::string& file : runEveryCommand(two, "--json --threads 2", reports / "two")) files.push_back(file);
    std::string arguments;
    for (const std::string& file : files) arguments += " '" + file + "'";
    const auto valid = test::runCommand("/usr/bin/python3 '" SCULPT_TESTS_DIR
                                        "/support/validate_json.py' '" SCULPT_DATA_DIR "/reports.schema.json'" +
                                            arguments,
                                        reports.path().string());
    EXPECT_EQ(valid.exitCode, 0) << valid.out << valid.err;

    const auto first = filesUnder(one.path()), second = filesUnder(two.path());
    ASSERT_EQ(first.size(), second.size());
    EXPECT_GT(first.size(), 30u);
    for (const auto& [name, bytes] : first) {
        ASSERT_TRUE(second.count(name)) << name;
        EXPECT_TRUE(second.at(name) == bytes) << name << " differs between one thread and two";
    }
}

// --quiet prints nothing on success; errors still get their one line.
TEST(Batch, QuietPrintsOnlyErrors)
{
    TempDir dir;
    auto r = runSculpt("new --radius 4 --voxel-size 0.5 -o a.vdb --quiet", dir.path());
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_EQ(r.out + r.err, "");
    r = runSculpt("smooth missing.vdb -o b.vdb -q", dir.path());
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

// A print shop's file: the three labels of a segmentation as three objects of one 3MF, in
// millimetres, each in its piece's colour, read back by lib3mf.
TEST(Batch, AThreeLabelImportGivesA3mfOfThreeObjectsInMillimetresWithTheirColours)
{
    TempDir dir;
    test::writeThreeLabelRaw(dir / "map.raw");
    const auto r = runSculpt("import map.raw --raw-dims 48,32,32 --labels -o labels.vdb --mesh labels.3mf", dir.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json info = nlohmann::json::parse(runSculpt("info labels.vdb --json", dir.path()).out);
    const test::ThreeMfModel model = test::readThreeMf(dir / "labels.3mf");
    ASSERT_TRUE(model.read);
    EXPECT_EQ(model.unit, 1);  // millimetres, as the document
    ASSERT_EQ(model.objects.size(), 3u);
    EXPECT_EQ(model.buildItems, 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        const nlohmann::json& piece = info["pieces"][i];
        EXPECT_EQ(model.objects[i].name, piece["name"].get<std::string>());
        for (int c = 0; c < 3; ++c)
            EXPECT_EQ(int(model.objects[i].colour[c]), int(std::lround(piece["colour"][c].get<double>() * 255.0)))
                << piece["name"];
        EXPECT_GT(model.objects[i].triangles, 100u);
    }
}

}  // namespace
}  // namespace sculpt
