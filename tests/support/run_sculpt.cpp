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

CommandResult runSculpt(const std::string& args, const std::string& workDir)
{
    return runCommand("'" SCULPT_EXECUTABLE "' " + args, workDir);
}

CommandResult runSculptBounded(const std::string& args, const std::string& workDir, int seconds, int addressSpaceMiB)
{
    return runCommand("ulimit -v " + std::to_string(addressSpaceMiB * 1024) + " && timeout " + std::to_string(seconds) +
                          " '" SCULPT_EXECUTABLE "' " + args,
                      workDir);
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
