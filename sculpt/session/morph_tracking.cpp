// SPDX-License-Identifier: Apache-2.0
#include "sculpt/session/morph_tracking.h"

namespace sculpt {

void TrackingTally::add(const TrackingStep& s)
{
    ++steps;
    splits += s.splits;
    collapses += s.collapses;
    inverted += s.inverted;
    quasiCritical += s.quasiCritical.size();
    surgeries += s.surgery.kind != SurgeryKind::None;
    reseeds += s.reseeded;
    vanished += s.vanishedShells;
    folds += s.folded;
}

void MorphTracking::frame(const FieldImage& field)
{
    if (!mTracker) mTracker.emplace(field);
    mSequence.add(mTracker->mesh(), mEditsSinceFrame);
    mEditsSinceFrame.clear();
    mFrames.push_back({measureQuality(mTracker->mesh()), mFlaggedSinceFrame, mSequence.segments().size() - 1});
    mFlaggedSinceFrame = 0;
}

void MorphTracking::step(const FieldImage& field)
{
    const TrackingStep report = mTracker->step(field);
    mTally.add(report);
    mFlaggedSinceFrame += report.quasiCritical.size();
    mEditsSinceFrame.insert(mEditsSinceFrame.end(), report.edits.begin(), report.edits.end());
}

TriangleMesh MorphTracking::frameMesh(int index) const
{
    const std::size_t segmentIndex = mFrames.at(std::size_t(index)).segment;
    const TrackedSegment& segment = mSequence.segments()[segmentIndex];
    return segment.frameMesh(std::size_t(index - segment.firstFrame));
}

}  // namespace sculpt
