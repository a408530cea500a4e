// SPDX-License-Identifier: Apache-2.0
#include "tests/support/run_sculpt.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace sculpt::test {

namespace {

std::string slurp(const std::string& path)
{
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

/// The exit code (128 + the signal for a killed one) and the output a command left in `workDir`.
CommandResult collectResult(int status, const std::string& workDir)
{
    CommandResult result;
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    result.out = slurp(workDir + "/.stdout");
    result.err = slurp(workDir + "/.stderr");
    std::remove((workDir + "/.stdout").c_str());
    std::remove((workDir + "/.stderr").c_str());
    return result;
}

}  // namespace

// gcc says __SANITIZE_ADDRESS__, clang (before 15) only __has_feature(address_sanitizer).
#if defined(__SANITIZE_ADDRESS__)
#define SCULPT_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#define SCULPT_ADDRESS_SANITIZER __has_feature(address_sanitizer)
#else
#define SCULPT_ADDRESS_SANITIZER 0
#endif

const char* sculptExecutable() { return SCULPT_EXECUTABLE; }

const std::vector<std::string>& sculptCommands()
{
    static const std::vector<std::string> commands{"new",    "info",    "mesh",   "smooth", "offset",
                                                   "morph",  "build",   "apply",  "import", "export-labels",
                                                   "hollow", "islands", "pieces", "render"};
    return commands;
}

CommandResult runSculpt(const std::string& args, const std::string& workDir)
{
    return runCommand("'" SCULPT_EXECUTABLE "' " + args, workDir);
}

CommandResult runSculptBounded(const std::string& args, const std::string& workDir, int seconds, int addressSpaceMiB)
{
#if SCULPT_ADDRESS_SANITIZER
    // AddressSanitizer reserves terabytes of shadow address space: cap its allocations and the
    // resident memory instead.
    const std::string mib = std::to_string(addressSpaceMiB);
    const std::string cap = "ASAN_OPTIONS=\"$ASAN_OPTIONS:max_allocation_size_mb=" + mib +
                            ":allocator_may_return_null=1:hard_rss_limit_mb=" + mib + "\" ";
#else
    const std::string cap = "ulimit -v " + std::to_string(addressSpaceMiB * 1024) + " && ";
#endif
    return runCommand(cap + "timeout " + std::to_string(seconds) + " '" SCULPT_EXECUTABLE "' " + args, workDir);
}

CommandResult runCommand(const std::string& command, const std::string& workDir)
{
    const std::string outFile = workDir + "/.stdout", errFile = workDir + "/.stderr";
    const std::string line =
        "cd '" + workDir + "' && " + command + " >'" + outFile + "' 2>'" + errFile + "' </dev/null";
    return collectResult(std::system(line.c_str()), workDir);
}

int startSculpt(const std::string& args, const std::string& workDir)
{
    const std::string line = "cd '" + workDir + "' && exec '" SCULPT_EXECUTABLE "' " + args + " >'" + workDir +
                             "/.stdout' 2>'" + workDir + "/.stderr' </dev/null";
    const pid_t pid = fork();
    if (pid == 0) {  // `exec`: the shell becomes sculpt, so the id is the program's own
        execl("/bin/sh", "sh", "-c", line.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    return int(pid);
}

CommandResult finishSculpt(int pid, const std::string& workDir)
{
    int status = 0;
    waitpid(pid_t(pid), &status, 0);
    return collectResult(status, workDir);
}

}  // namespace sculpt::test
