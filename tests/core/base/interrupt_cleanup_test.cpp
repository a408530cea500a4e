// SPDX-License-Identifier: Apache-2.0
// An interruption (Ctrl-C, a scheduler's SIGTERM) ends the program at once, with the exit code
// shells expect, and leaves no half-written file; finished files stay.

#include "core/base/atomic_file.h"
#include "core/base/interrupt_cleanup.h"
#include "tests/support/temp_dir.h"

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace sculpt {
namespace {

namespace fs = std::filesystem;

/// Runs `body` in a child process and returns its exit code (128 + N if signal N killed it).
template <typename Body>
int exitCodeOf(const Body& body)
{
    const pid_t pid = fork();
    if (pid == 0) {
        body();
        _exit(0);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

/// Writes a finished file, starts another and is interrupted by `signal` while writing it.
void interruptedWhileWriting(const fs::path& dir, int signal)
{
    exitCleanlyOnInterrupt("test");
    writeFileAtomically(dir / "finished.txt", "whole\n");
    AtomicFile file(dir / "document.vdb");
    std::ofstream(file.temporaryPath()) << "half a document";
    raise(signal);
    _exit(0);  // not reached: the handler exits
}

TEST(InterruptCleanup, SigintAndSigtermRemoveTheTemporaryAndExitAsShellsExpect)
{
    for (const auto& [signal, code] : {std::pair{SIGINT, 130}, std::pair{SIGTERM, 143}, std::pair{SIGHUP, 129}}) {
        test::TempDir dir;
        EXPECT_EQ(exitCodeOf([&] { interruptedWhileWriting(dir.path(), signal); }), code) << signal;
        EXPECT_EQ(dir.entries(), std::vector<std::string>{"finished.txt"}) << signal;
    }
}

// `nohup` and a shell's background jobs ignore a signal before the program starts: it stays ignored.
TEST(InterruptCleanup, ASignalIgnoredAtStartStaysIgnored)
{
    test::TempDir dir;
    const int code = exitCodeOf([&] {
        std::signal(SIGHUP, SIG_IGN);
        exitCleanlyOnInterrupt("test");
        raise(SIGHUP);
        writeFileAtomically(dir / "after.txt", "still running\n");
    });
    EXPECT_EQ(code, 0);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"after.txt"});
}

// Without an interruption, registering costs nothing visible: temporaries come and go as before.
TEST(InterruptCleanup, TicketsAreReusedSoManyWritesNeverRunOut)
{
    test::TempDir dir;
    for (int i = 0; i < 500; ++i) {
        AtomicFile file(dir / "again.txt");
        std::ofstream(file.temporaryPath()) << i;
        file.commit();
    }
    const int ticket = registerTemporary(dir / "x");
    EXPECT_GE(ticket, 0);
    forgetTemporary(ticket);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"again.txt"});
}

}  // namespace
}  // namespace sculpt
