// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file morph_frames.h
/// @brief The frames of a finished morph (Morph panel), shown one at a time in the view in place
///        of the document: played, paused, stepped, scrubbed, kept as the document or exported.
///        The document itself changes only when a frame is kept (one undo step).

#include "core/mesh/incremental_mesher.h"
#include "sculpt/session/morph_run.h"

#include <memory>

namespace sculpt::ui {

class MorphFrames {
public:
    static constexpr double kFramesPerSecond = 8.0;

    /// Shows the last frame (the morph's result). `run` must hold at least one frame.
    explicit MorphFrames(MorphRun run);

    int count() const { return int(mRun.frames.size()); }
    int shown() const { return mShown; }
    /// Shows frame `index` (clamped), meshing it (a full mesh of that frame).
    void show(int index);
    const FieldImage& shownField() const { return mRun.frames[std::size_t(mShown)]; }
    /// The shown frame's mesh; a new mesher object per frame, so the display re-uploads it.
    const IncrementalMesher& mesher() const { return *mMesher; }
    const MorphRun& run() const { return mRun; }

    bool playing() const { return mPlaying; }
    /// Starts (from the first frame if at the last) or pauses playback, at time `now` (seconds).
    void togglePlay(double now);
    /// Shows the frame due at time `now` while playing (frames may be skipped); stops at the last.
    void tick(double now);

private:
    MorphRun mRun;
    int mShown = -1;
    std::unique_ptr<IncrementalMesher> mMesher;
    bool mPlaying = false;
    double mPlayStart = 0.0;  // when playback began, and from which frame
    int mPlayFrom = 0;
};

}  // namespace sculpt::ui
