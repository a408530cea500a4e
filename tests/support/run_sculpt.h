// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file run_sculpt.h
/// @brief Runs the real `sculpt` executable (path from the build) for end-to-end tests.

#include <string>
#include <vector>

namespace sculpt::test {

struct CommandResult {
    int exitCode = -1;
    std::string out;  ///< standard output
    std::string err;  ///< standard error
};

/// The path of the `sculpt` executable under test.
const char* sculptExecutable();
/// Every command the program has (the tests that go through them all fail for one left out).
const std::vector<std::string>& sculptCommands();

/// Runs `sculpt ARGS` through the shell in `workDir`; ARGS must already be shell-safe.
CommandResult runSculpt(const std::string& args, const std::string& workDir);
/// runSculpt killed after `seconds` and refused more than `addressSpaceMiB` of address space.
CommandResult runSculptBounded(const std::string& args, const std::string& workDir, int seconds, int addressSpaceMiB);

/// Starts `sculpt ARGS` in `workDir` without waiting (its output kept as runSculpt's); returns its
/// process id for signals and finishSculpt.
int startSculpt(const std::string& args, const std::string& workDir);
/// Waits for what startSculpt started and gives its result.
CommandResult finishSculpt(int pid, const std::string& workDir);

/// Runs `COMMAND` (a shell command line, already shell-safe) in `workDir`.
CommandResult runCommand(const std::string& command, const std::string& workDir);

}  // namespace sculpt::test
