// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file frame_log.h
/// @brief What the frames did since the last report, for replays and benchmarks: how long each
///        took, how long an input waited to be seen (a stamp, a mode's preview), what the mesher
///        re-meshed, how many triangles were drawn; and when the last input came.

#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <vector>

namespace sculpt {
class SculptSession;
}  // namespace sculpt

namespace sculpt::ui {

class FrameLog {
public:
    /// Another document or piece is shown: the mesher's counts start from `session`'s.
    void restart(const SculptSession& session);
    /// An input came at `now` (the window's clock), due at `arrival` (a replayed one's time).
    void input(double now, double arrival);
    /// Something changed on screen without input (a notice): frames go on a little.
    void wake(double now) { mLastInput = now; }
    double lastInput() const { return mLastInput; }
    /// The latest input added `stamps` stamps to the model: the next frame shows them.
    void awaitStamps(std::size_t stamps);
    /// The open mode's preview changed for the latest input: the next frame shows it.
    void awaitPreview();

    /// A frame begins at `now`: the blocks `session` re-meshed for it are counted. @return the
    /// seconds since the previous frame began.
    double begin(double now, const SculptSession& session);
    /// The frame that began at `start` ended at `end`, `triangles` drawn; `measured`: its time
    /// counts (a frame writing a report does not). @return its milliseconds.
    double end(double start, double end, double triangles, bool measured);
    std::uint64_t framesDrawn() const { return mFramesDrawn; }

    /// The figures since the last report (frame times, latencies, stamps, re-meshed blocks,
    /// what the mesher told viewers of `session`); they start again.
    void report(nlohmann::json& out, const SculptSession& session);

private:
    std::vector<double> mFrameMs, mLatencyMs, mPreviewLatencyMs, mTrianglesDrawn;
    std::size_t mStamps = 0;
    double mStampsSince = -1.0;   // stamps not yet on screen: when their input came
    double mPreviewSince = -1.0;  // a mode's preview not yet on screen: when its input came
    double mLastInput = 0.0, mLastArrival = 0.0, mLastFrame = 0.0;
    std::size_t mRemeshedAtSync = 0, mRemeshed = 0;
    std::uint64_t mReportVersion = 0;
    std::uint64_t mFramesDrawn = 0;
};

}  // namespace sculpt::ui
