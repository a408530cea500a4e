#include "tests/support/run_sculpt.h"

#include <sys/wait.h>

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

}  // namespace

// gcc says __SANITIZE_ADDRESS__, clang (before 15) only __has_feature(address_sanitizer).
#if defined(__SANITIZE_ADDRESS__)
#define SCULPT_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#define SCULPT_ADDRESS_SANITIZER __has_feature(address_sanitizer)
#else
#define SCULPT_ADDRESS_SANITIZER 0
#endif

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
    const int status = std::system(line.c_str());
    CommandResult result;
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    result.out = slurp(outFile);
    result.err = slurp(errFile);
    std::remove(outFile.c_str());
    std::remove(errFile.c_str());
    return result;
}

}  // namespace sculpt::test
