// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file event_player.h
/// @brief Replays a recording (--play) at the pace it was recorded, on the window's clock: each
///        frame takes the events whose time has come, ending the frame early after a button,
///        key, text, resize, screenshot or report event (so ImGui sees each press and release in
///        its own frame, and a screenshot shows everything before it and nothing after). A wait
///        event holds it (a job runs); the events after keep their spacing.

#include "ui/input/input_event.h"

#include <vector>

namespace sculpt::ui {

class EventPlayer {
public:
    explicit EventPlayer(std::vector<InputEvent> events) : mEvents(std::move(events)) {}

    /// The replay's clock starts at `now` (the window's seconds).
    void start(double now) { mStart = now; }
    /// The events of this frame at `now` (none while held).
    std::vector<InputEvent> take(double now);
    /// Every event was taken, and nothing holds the replay.
    bool finished() const { return mNext >= mEvents.size() && !held(); }
    /// Holds the replay from `now` until resume().
    void hold(double now) { mHeldSince = now; }
    /// Ends a hold at `now`: the events after it keep their recorded spacing.
    void resume(double now);
    bool held() const { return mHeldSince >= 0.0; }
    /// When `event` was due on the window's clock.
    double arrival(const InputEvent& event) const { return mStart + event.time; }

private:
    std::vector<InputEvent> mEvents;
    std::size_t mNext = 0;
    double mStart = -1.0;      // the window's time the replay began
    double mHeldSince = -1.0;  // a wait event holds it: since when
};

}  // namespace sculpt::ui
