// The program as a batch job runs it: interrupted by Ctrl-C or a scheduler, under a memory limit.

#include "tests/support/run_sculpt.h"
#include "tests/support/temp_dir.h"

#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
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

}  // namespace
}  // namespace sculpt
