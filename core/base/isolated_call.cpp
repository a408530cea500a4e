// SPDX-License-Identifier: Apache-2.0
#include "core/base/isolated_call.h"

#include "core/base/errors.h"
#include "core/base/memory_budget.h"
#include "core/base/text_format.h"

#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <new>
#include <poll.h>
#include <signal.h>

namespace sculpt {

namespace {

// The reply on the pipe: a kind byte, then length-prefixed header and body.
constexpr char kReplied = 'R', kRefused = 'E', kOutOfMemory = 'M', kFailed = 'X';
constexpr std::size_t kSubjectPageBytes = 4096;
constexpr std::uint64_t kHeaderLimit = 64u << 20;  // headers are descriptions, never samples

/// Where the child writes the file it is decoding: a page shared with the parent.
char* gSubjectPage = nullptr;

/// Sets a soft limit, keeping any lower one the parent runs under (ulimit -v, -t).
void lowerLimit(int resource, rlim_t value)
{
    rlimit limit{};
    getrlimit(resource, &limit);
    limit.rlim_cur = std::min({limit.rlim_cur, limit.rlim_max, value});
    setrlimit(resource, &limit);
}

void writeAll(int fd, const void* data, std::size_t bytes)
{
    const char* p = static_cast<const char*>(data);
    while (bytes > 0) {
        const ssize_t n = write(fd, p, bytes);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) _exit(3);  // the parent is gone
        p += n;
        bytes -= std::size_t(n);
    }
}

void sendPart(int fd, const void* data, std::uint64_t bytes)
{
    writeAll(fd, &bytes, sizeof bytes);
    writeAll(fd, data, bytes);
}

/// The wall clock a child may take: twice its processor time and half a minute more, since on
/// a loaded machine a busy child gets less than a core.
int wallSeconds(const IsolationLimits& limits) { return 2 * limits.cpuSeconds + 30; }

void send(int fd, char kind, const ChildReply& reply)
{
    writeAll(fd, &kind, 1);
    sendPart(fd, reply.header.data(), reply.header.size());
    sendPart(fd, reply.body, reply.bodyBytes);
}

/// The child's side: limits, silence, the work, the reply; never returns.
[[noreturn]] void runChild(int fd, const IsolationLimits& limits, const std::function<ChildReply()>& work)
{
    for (const int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGXCPU, SIGTERM, SIGINT, SIGPIPE})
        std::signal(sig, SIG_DFL);  // the parent's handlers (autosave on a crash) are not the child's
    const int null = open("/dev/null", O_RDWR);
    for (const int stdFd : {0, 1, 2}) dup2(null, stdFd);
    lowerLimit(RLIMIT_CPU, rlim_t(limits.cpuSeconds));
    lowerLimit(RLIMIT_AS, addressSpaceBytes() + limits.memoryBytes);
    try {
        send(fd, kReplied, work());
    } catch (const InputError& e) {
        send(fd, kRefused, {e.what()});
    } catch (const std::bad_alloc&) {
        send(fd, kOutOfMemory, {});
    } catch (const std::exception& e) {
        send(fd, kFailed, {e.what()});
    } catch (...) {
        send(fd, kFailed, {"an unknown exception"});
    }
    _exit(0);
}

/// Reads from the child's pipe until it closes, the deadline passes (false) or the reply
/// claims more than `bodyLimit`.
class ReplyReader {
public:
    ReplyReader(int fd, std::chrono::steady_clock::time_point deadline) : mFd(fd), mDeadline(deadline) {}

    bool readKind(char& kind) { return readExactly(&kind, 1); }

    bool readPart(std::uint64_t limit, std::string& header)
    {
        std::uint64_t bytes = 0;
        if (!readExactly(&bytes, sizeof bytes) || bytes > limit) return false;
        header.resize(bytes);
        return readExactly(header.data(), bytes);
    }

    bool readBody(std::uint64_t limit, IsolatedBytes& out)
    {
        std::uint64_t bytes = 0;
        if (!readExactly(&bytes, sizeof bytes) || bytes > limit) return false;
        out.body.reset(static_cast<char*>(std::malloc(std::max<std::uint64_t>(bytes, 1))));
        if (!out.body) throw std::bad_alloc();
        out.bodyBytes = bytes;
        return readExactly(out.body.get(), bytes);
    }

    bool timedOut() const { return mTimedOut; }

private:
    bool readExactly(void* data, std::size_t bytes)
    {
        char* p = static_cast<char*>(data);
        while (bytes > 0) {
            const auto left =
                std::chrono::duration_cast<std::chrono::milliseconds>(mDeadline - std::chrono::steady_clock::now());
            if (left.count() <= 0) return !(mTimedOut = true);
            pollfd ready{mFd, POLLIN, 0};
            if (poll(&ready, 1, int(std::min<long long>(left.count(), 1000))) <= 0) continue;
            const ssize_t n = read(mFd, p, bytes);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) return false;
            p += n;
            bytes -= std::size_t(n);
        }
        return true;
    }

    int mFd;
    std::chrono::steady_clock::time_point mDeadline;
    bool mTimedOut = false;
};

/// Why the child ended without a whole reply, in the user's words.
std::string deathOf(int status, bool timedOut, const IsolationLimits& limits)
{
    if (timedOut) return "took longer than " + std::to_string(wallSeconds(limits)) + " s";
    if (WIFSIGNALED(status) && WTERMSIG(status) == SIGXCPU)
        return "took more than " + std::to_string(limits.cpuSeconds) + " s of processor time";
    if (WIFSIGNALED(status)) return std::string("crashed: ") + strsignal(WTERMSIG(status));
    return "crashed: it ended with status " + std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : status);
}

std::string subjectNamed(const char* page, const IsolationLimits& limits)
{
    return page[0] != '\0' ? std::string(page, strnlen(page, kSubjectPageBytes - 1)) : limits.subject;
}

/// A shared page, unmapped when it goes.
struct SharedPage {
    char* bytes =
        static_cast<char*>(mmap(nullptr, kSubjectPageBytes, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0));
    SharedPage()
    {
        if (bytes == MAP_FAILED) throw std::runtime_error("cannot map a page for a child process");
        bytes[0] = '\0';
    }
    ~SharedPage() { munmap(bytes, kSubjectPageBytes); }
};

bool gIsolation = true;

/// What runIsolated returns, from `work` run here: its exceptions propagate as they are.
IsolatedBytes runInProcess(const std::function<ChildReply()>& work)
{
    const ChildReply made = work();
    IsolatedBytes reply;
    reply.header = made.header;
    reply.body.reset(static_cast<char*>(std::malloc(std::max<std::size_t>(made.bodyBytes, 1))));
    if (!reply.body) throw std::bad_alloc();
    if (made.bodyBytes > 0) std::memcpy(reply.body.get(), made.body, made.bodyBytes);
    reply.bodyBytes = made.bodyBytes;
    return reply;
}

}  // namespace

void noteIsolatedSubject(const std::string& subject)
{
    if (!gSubjectPage) return;
    const std::size_t n = std::min(subject.size(), kSubjectPageBytes - 1);
    std::memcpy(gSubjectPage, subject.data(), n);
    gSubjectPage[n] = '\0';
}

void setIsolation(bool enabled) { gIsolation = enabled; }

IsolatedBytes runIsolated(const IsolationLimits& limits, const std::function<ChildReply()>& work)
{
    if (!gIsolation) return runInProcess(work);
    SharedPage page;
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error("cannot open a pipe to a child process");
    const pid_t pid = fork();
    if (pid < 0) {
        close(fds[0]);
        close(fds[1]);
        throw std::runtime_error("cannot start a child process: " + std::string(std::strerror(errno)));
    }
    if (pid == 0) {
        close(fds[0]);
        gSubjectPage = page.bytes;
        runChild(fds[1], limits, work);
    }
    close(fds[1]);
    ReplyReader reader(fds[0], std::chrono::steady_clock::now() + std::chrono::seconds(wallSeconds(limits)));
    IsolatedBytes reply;
    char kind = 0;
    const bool whole = reader.readKind(kind) && reader.readPart(kHeaderLimit, reply.header) &&
                       reader.readBody(limits.memoryBytes, reply);
    if (!whole) kill(pid, SIGKILL);
    close(fds[0]);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
    const std::string who = subjectNamed(page.bytes, limits) + ": " + limits.reader;
    if (!whole) throw InputError(who + " failed on this file (" + deathOf(status, reader.timedOut(), limits) + ")");
    if (kind == kRefused) throw InputError(reply.header);
    if (kind == kOutOfMemory)
        throw InputError(who + " needed more than " + formatBytes(double(limits.memoryBytes)) + " of memory");
    if (kind == kFailed) throw InputError(who + " failed on this file (" + reply.header + ")");
    return reply;
}

}  // namespace sculpt
