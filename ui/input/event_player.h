#pragma once
/// @file event_player.h
/// @brief Replays a recording (--play) at the pace it was recorded: each frame takes the events
///        whose time has come, ending the frame early after a button, key, text, resize,
///        screenshot or report event (so ImGui sees each press and release in its own frame,
///        and a screenshot shows everything before it and nothing after).

#include "ui/input/input_event.h"

#include <vector>

namespace sculpt::ui {

class EventPlayer {
public:
    explicit EventPlayer(std::vector<InputEvent> events) : mEvents(std::move(events)) {}

    /// The events of this frame, `elapsed` seconds after the replay began.
    std::vector<InputEvent> take(double elapsed);
    bool finished() const { return mNext >= mEvents.size(); }

private:
    std::vector<InputEvent> mEvents;
    std::size_t mNext = 0;
};

}  // namespace sculpt::ui
