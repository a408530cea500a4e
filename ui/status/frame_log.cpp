// SPDX-License-Identifier: Apache-2.0
#include "ui/status/frame_log.h"

#include "sculpt/session/sculpt_session.h"

#include <nlohmann/json.hpp>

namespace sculpt::ui {

void FrameLog::restart(const SculptSession& session)
{
    mRemeshedAtSync = session.remeshedBlocks();
    mReportVersion = session.mesher()->version();
}

void FrameLog::input(double now, double arrival)
{
    mLastInput = now;
    mLastArrival = arrival;
}

void FrameLog::awaitStamps(std::size_t stamps)
{
    mStamps += stamps;
    if (mStampsSince < 0.0) mStampsSince = mLastArrival;
}

void FrameLog::awaitPreview()
{
    if (mPreviewSince < 0.0) mPreviewSince = mLastArrival;
}

double FrameLog::begin(double now, const SculptSession& session)
{
    const std::size_t remeshed = session.remeshedBlocks();
    mRemeshed += remeshed - mRemeshedAtSync;
    mRemeshedAtSync = remeshed;
    return now - mLastFrame;
}

double FrameLog::end(double start, double end, double triangles, bool measured)
{
    const double frameMs = 1000.0 * (end - start);
    if (measured) {
        mFrameMs.push_back(frameMs);
        mTrianglesDrawn.push_back(triangles);
    }
    const auto seen = [end](double& since, std::vector<double>& latencies) {  // what waited is on screen now
        if (since < 0.0) return;
        latencies.push_back(1000.0 * (end - since));
        since = -1.0;
    };
    seen(mPreviewSince, mPreviewLatencyMs);
    seen(mStampsSince, mLatencyMs);
    mLastFrame = start;
    ++mFramesDrawn;
    return frameMs;
}

void FrameLog::report(nlohmann::json& out, const SculptSession& session)
{
    out["frame"] = mFramesDrawn;
    out["remeshed"] = mRemeshed;  // blocks the mesher re-meshed, empty candidates included
    const IncrementalMesher::Changes changes = session.mesher()->changesSince(mReportVersion);
    out["mesher_changed"] = changes.updated.size() + changes.removed.size();  // what it reports to viewers
    mReportVersion = session.mesher()->version();
    mRemeshed = 0;
    out["frame_times_ms"] = mFrameMs;
    out["latencies_ms"] = mLatencyMs;
    out["preview_latencies_ms"] = mPreviewLatencyMs;
    out["stamps"] = mStamps;
    out["triangles_drawn_per_frame"] = mTrianglesDrawn;
    mFrameMs.clear(), mLatencyMs.clear(), mPreviewLatencyMs.clear(), mTrianglesDrawn.clear();
    mStamps = 0;
}

}  // namespace sculpt::ui
