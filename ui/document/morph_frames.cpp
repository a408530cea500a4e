// SPDX-License-Identifier: Apache-2.0
#include "ui/document/morph_frames.h"

#include <algorithm>

namespace sculpt::ui {

MorphFrames::MorphFrames(MorphRun run) : mRun(std::move(run)) { show(count() - 1); }

void MorphFrames::show(int index)
{
    index = std::clamp(index, 0, count() - 1);
    if (index == mShown && mMesher) return;
    mMesher = std::make_unique<IncrementalMesher>();  // a new id: the display uploads it all
    mMesher->rebuild(mRun.frames[std::size_t(index)]);
    mShown = index;
}

void MorphFrames::togglePlay(double now)
{
    mPlaying = !mPlaying;
    if (mPlaying && mShown == count() - 1) show(0);
    mPlayStart = now;
    mPlayFrom = mShown;
}

void MorphFrames::tick(double now)
{
    if (!mPlaying) return;
    // By the clock, not by frames drawn: a slow frame skips ahead instead of slowing the morph.
    show(mPlayFrom + int((now - mPlayStart) * kFramesPerSecond));
    if (mShown == count() - 1) mPlaying = false;
}

}  // namespace sculpt::ui
