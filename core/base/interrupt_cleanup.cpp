// SPDX-License-Identifier: Apache-2.0
#include "core/base/interrupt_cleanup.h"

#include <unistd.h>

#include <climits>

#include <array>
#include <atomic>
#include <csignal>
#include <cstring>

namespace sculpt {

namespace {

// A handler may only use what is async-signal-safe: fixed slots, lock-free atomics, unlink, write.
enum SlotState : int { kFree, kFilling, kRegistered };
constexpr int kSlots = 64;  // temporaries written at the same time; a morph has two
std::array<std::atomic<int>, kSlots> gStates{};
std::array<std::array<char, PATH_MAX>, kSlots> gPaths{};
const char* gProgram = "sculpt";

void writeText(const char* text)
{
    const ssize_t ignored = write(STDERR_FILENO, text, std::strlen(text));
    (void)ignored;
}

void removeTemporariesAndExit(int signal)
{
    for (int i = 0; i < kSlots; ++i)
        if (gStates[std::size_t(i)].load() == kRegistered) unlink(gPaths[std::size_t(i)].data());
    writeText(gProgram);
    writeText(": interrupted (no partial file left)\n");
    _exit(128 + signal);
}

}  // namespace

int registerTemporary(const std::filesystem::path& path)
{
    const std::string text = std::filesystem::absolute(path).string();  // the handler cannot know the directory
    if (text.size() >= PATH_MAX) return -1;
    for (int i = 0; i < kSlots; ++i) {
        int expected = kFree;
        if (!gStates[std::size_t(i)].compare_exchange_strong(expected, kFilling)) continue;
        std::memcpy(gPaths[std::size_t(i)].data(), text.c_str(), text.size() + 1);
        gStates[std::size_t(i)].store(kRegistered);
        return i;
    }
    return -1;
}

void forgetTemporary(int ticket)
{
    if (ticket >= 0 && ticket < kSlots) gStates[std::size_t(ticket)].store(kFree);
}

void exitCleanlyOnInterrupt(const char* program)
{
    gProgram = program;
    for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
        struct sigaction current {};
        sigaction(signal, nullptr, &current);
        if (current.sa_handler == SIG_IGN) continue;
        struct sigaction action {};
        action.sa_handler = removeTemporariesAndExit;
        sigfillset(&action.sa_mask);  // a second signal waits: the first one's exit wins
        sigaction(signal, &action, nullptr);
    }
}

}  // namespace sculpt
