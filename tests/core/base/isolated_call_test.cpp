// SPDX-License-Identifier: Apache-2.0
#include "core/base/errors.h"
#include "core/base/isolated_call.h"

#include <gtest/gtest.h>

#include <csignal>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <vector>

namespace sculpt {
namespace {

IsolationLimits limits(int cpuSeconds = 60)
{
    IsolationLimits l;
    l.subject = "scan.dcm";
    l.reader = "the test reader";
    l.memoryBytes = 512u << 20;
    l.cpuSeconds = cpuSeconds;
    return l;
}

/// The InputError runIsolated throws for `work`, or "" if it returned.
std::string refusal(const std::function<ChildReply()>& work, const IsolationLimits& l = limits())
{
    try {
        runIsolated(l, work);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(IsolatedCall, TheChildsHeaderAndBodyArriveWhole)
{
    auto samples = std::make_shared<std::vector<std::uint32_t>>(3u << 20);  // 12 MB: many pipe buffers
    for (std::size_t i = 0; i < samples->size(); ++i) (*samples)[i] = std::uint32_t(i * 2654435761u);
    const IsolatedBytes bytes = runIsolated(limits(), [&] {
        ChildReply reply{"header", samples->data(), samples->size() * sizeof(std::uint32_t)};
        reply.owner = samples;
        return reply;
    });
    EXPECT_EQ(bytes.header, "header");
    ASSERT_EQ(bytes.bodyBytes, samples->size() * sizeof(std::uint32_t));
    EXPECT_EQ(std::memcmp(bytes.body.get(), samples->data(), bytes.bodyBytes), 0);
}

TEST(IsolatedCall, WithIsolationOffTheWorkRunsHereAndItsReplyArrivesTheSame)
{
    setIsolation(false);  // as the fuzz targets run
    int ranHere = 0;      // a child's write would never reach this process
    const std::string body = "samples";
    const IsolatedBytes bytes = runIsolated(limits(), [&] {
        ++ranHere;
        return ChildReply{"header", body.data(), body.size()};
    });
    EXPECT_THROW(runIsolated(limits(), []() -> ChildReply { throw InputError("scan.dcm: bad"); }), InputError);
    setIsolation(true);
    EXPECT_EQ(ranHere, 1);
    EXPECT_EQ(bytes.header, "header");
    ASSERT_EQ(bytes.bodyBytes, body.size());
    EXPECT_EQ(std::string(bytes.body.get(), bytes.bodyBytes), body);
}

TEST(IsolatedCall, AnInputErrorInTheChildIsThrownWithItsMessage)
{
    EXPECT_EQ(refusal([]() -> ChildReply { throw InputError("scan.dcm: no image orientation"); }),
              "scan.dcm: no image orientation");
}

TEST(IsolatedCall, AnAbortOrACrashEndsOnlyTheChildAndNamesTheFileItWasReading)
{
    const std::string aborted = refusal([]() -> ChildReply {
        noteIsolatedSubject("series/slice_7.dcm");
        std::abort();
    });
    EXPECT_EQ(aborted.rfind("series/slice_7.dcm: the test reader failed on this file (crashed", 0), 0u) << aborted;
    const std::string crashed = refusal([]() -> ChildReply {
        std::raise(SIGSEGV);
        return {};
    });
    EXPECT_EQ(crashed.rfind("scan.dcm: the test reader failed on this file (crashed", 0), 0u) << crashed;
    // Outside a child, naming a subject does nothing.
    noteIsolatedSubject("elsewhere.dcm");
    EXPECT_EQ(refusal([]() -> ChildReply { std::abort(); }).rfind("scan.dcm:", 0), 0u);
}

TEST(IsolatedCall, AnAllocationBeyondTheLimitIsRefusedNamingTheFile)
{
    const std::string refused = refusal([]() -> ChildReply {
        std::vector<char> huge(std::size_t(4) << 30, 1);  // 4 GB against a limit of 512 MB
        return {std::string(1, huge.back())};
    });
    EXPECT_EQ(refused.rfind("scan.dcm: the test reader", 0), 0u) << refused;
}

TEST(IsolatedCall, AnEndlessLoopStopsAtTheProcessorTimeLimit)
{
    const std::string refused = refusal(
        []() -> ChildReply {
            for (volatile unsigned i = 0;; i = i + 1) {}
        },
        limits(1));
    EXPECT_NE(refused.find("took more than 1 s of processor time"), std::string::npos) << refused;
}

TEST(IsolatedCall, TheChildsChatterNeverReachesTheTerminal)
{
    testing::internal::CaptureStderr();
    testing::internal::CaptureStdout();
    runIsolated(limits(), [] {
        std::cerr << "MetaImage: Read: Cannot open data file" << std::endl;
        std::fprintf(stdout, "gdcm chatter\n");
        std::fflush(stdout);
        return ChildReply{"ok"};
    });
    EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

}  // namespace
}  // namespace sculpt
