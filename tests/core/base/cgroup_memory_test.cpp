// SPDX-License-Identifier: Apache-2.0
// The memory a control group leaves us, read from fixture hierarchies laid out as the kernel's:
// cgroup v2 (Slurm, systemd, Docker on current hosts) and v1's memory controller (older hosts).

#include "core/base/cgroup_memory.h"
#include "core/base/errors.h"
#include "core/base/memory_budget.h"
#include "tests/support/temp_dir.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace sculpt {
namespace {

namespace fs = std::filesystem;

void writeText(const fs::path& file, const std::string& text)
{
    fs::create_directories(file.parent_path());
    std::ofstream(file) << text;
}

std::string mountLine(const std::string& root, const fs::path& mountPoint, const std::string& typeAndOptions)
{
    return "35 31 0:32 " + root + " " + mountPoint.string() + " rw,relatime - " + typeAndOptions + "\n";
}

// A job limited to 200 MB with a step below it: the job's limit binds, less its working set (the
// inactive file cache does not count: the kernel drops it first).
TEST(CgroupMemory, AV2LimitAboveTheProcessesGroupBindsLessTheWorkingSet)
{
    test::TempDir dir;
    const fs::path unified = dir / "unified";
    writeText(unified / "slurm/job_7/memory.max", "200000000\n");
    writeText(unified / "slurm/job_7/memory.current", "50000000\n");
    writeText(unified / "slurm/job_7/memory.stat", "anon 20000000\nfile 30000000\ninactive_file 10000000\n");
    writeText(unified / "slurm/job_7/step_0/memory.max", "max\n");
    writeText(unified / "slurm/job_7/step_0/memory.current", "40000000\n");
    const std::string mounts = mountLine("/", "/proc", "proc proc rw") + mountLine("/", unified, "cgroup2 cgroup2 rw");
    EXPECT_EQ(cgroupMemoryLeft("0::/slurm/job_7/step_0\n", mounts), 200000000u - (50000000u - 10000000u));
    // No limit anywhere: none.
    fs::remove(unified / "slurm/job_7/memory.max");
    EXPECT_EQ(cgroupMemoryLeft("0::/slurm/job_7/step_0\n", mounts), std::nullopt);
}

// A container sees its own group as the mount's root (a cgroup namespace): the path is relative.
TEST(CgroupMemory, AContainersGroupIsTheMountsRoot)
{
    test::TempDir dir;
    const fs::path unified = dir / "cgroup with space";
    writeText(unified / "memory.max", "1073741824\n");
    writeText(unified / "memory.current", "73741824\n");
    std::string escaped = unified.string();
    escaped.replace(escaped.find(' '), 1, "\\040");
    escaped.replace(escaped.find(' '), 1, "\\040");
    const std::string mounts = "35 31 0:32 / " + escaped + " rw - cgroup2 cgroup2 rw\n";
    EXPECT_EQ(cgroupMemoryLeft("0::/\n", mounts), 1000000000u);
}

// v1: the memory controller's own hierarchy; "no limit" is a huge number, and the tighter of the
// two hierarchies binds when a host mounts both.
TEST(CgroupMemory, TheV1MemoryControllerAndTheTighterOfBothHierarchies)
{
    test::TempDir dir;
    const fs::path memory = dir / "memory", unified = dir / "unified";
    writeText(memory / "memory.limit_in_bytes", "9223372036854771712\n");
    writeText(memory / "batch/memory.limit_in_bytes", "300000000\n");
    writeText(memory / "batch/memory.usage_in_bytes", "100000000\n");
    writeText(memory / "batch/memory.stat", "cache 0\ntotal_inactive_file 25000000\n");
    const std::string cgroups = "4:memory:/batch\n1:cpu,cpuacct:/\n0::/\n";
    std::string mounts =
        mountLine("/", memory, "cgroup cgroup rw,memory") + mountLine("/", dir / "cpu", "cgroup cgroup rw,cpu,cpuacct");
    EXPECT_EQ(cgroupMemoryLeft(cgroups, mounts), 300000000u - 75000000u);
    writeText(unified / "memory.max", "100000000\n");
    writeText(unified / "memory.current", "0\n");
    mounts += mountLine("/", unified, "cgroup2 cgroup2 rw");
    EXPECT_EQ(cgroupMemoryLeft(cgroups, mounts), 100000000u);
    // Using more than the limit (it can, briefly) leaves nothing, not a wrapped-around number.
    writeText(memory / "batch/memory.usage_in_bytes", "400000000\n");
    writeText(memory / "batch/memory.stat", "\n");
    EXPECT_EQ(cgroupMemoryLeft(cgroups, mounts), 0u);
}

// Under `ulimit -v` the address space left binds, and the refusal says so.
TEST(CgroupMemory, AnAddressSpaceLimitBindsAndIsNamed)
{
    const pid_t pid = fork();
    if (pid == 0) {
        rlimit limit{};
        limit.rlim_cur = limit.rlim_max = addressSpaceBytes() + (100u << 20);
        setrlimit(RLIMIT_AS, &limit);
        const MemoryLimit bound = memoryLimit();
        const bool named = bound.source == "the address-space limit, ulimit -v";
        const bool sized = bound.bytes > (90u << 20) && bound.bytes <= (100u << 20);
        bool refused = false;
        try {
            requireMemory(double(200u << 20), "the test");
        } catch (const InputError& e) {
            refused = std::string(e.what()).find("under the address-space limit") != std::string::npos;
        }
        _exit(named && sized && refused ? 0 : 1);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
}

}  // namespace
}  // namespace sculpt
