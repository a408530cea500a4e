// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file replay.h
/// @brief The window's scripted side: a recording played (--play) or made (--record), and the
///        screenshots and reports that events ask for, written once the frame after them is drawn.

#include "ui/input/event_player.h"
#include "ui/input/input_event.h"

#include <filesystem>
#include <memory>
#include <vector>

namespace sculpt::ui {

class Replay {
public:
    /// Plays the recording at `play` (empty: none), records into `record` (empty: none).
    Replay(const std::filesystem::path& play, std::filesystem::path record);

    /// The recording played, or nullptr.
    EventPlayer* player() { return mPlayer.get(); }
    const EventPlayer* player() const { return mPlayer.get(); }
    /// When `event` was due on the window's clock (a live one: when it came).
    double arrival(const InputEvent& event) const { return mPlayer ? mPlayer->arrival(event) : event.time; }
    /// Takes `event` in: a user's input is recorded, a screenshot or a report is asked for.
    void note(const InputEvent& event);
    /// Asks for a screenshot of the next frame at `path`.
    void askScreenshot(const std::filesystem::path& path);
    /// Screenshots or reports wait for the frame's end.
    bool asked() const { return !mAsked.empty(); }
    /// They, in the order asked; none wait after.
    std::vector<InputEvent> takeAsked() { return std::move(mAsked); }
    /// Writes the recording, if one is made.
    void save() const;

private:
    std::unique_ptr<EventPlayer> mPlayer;
    std::filesystem::path mRecordTo;
    std::vector<InputEvent> mRecording, mAsked;
};

}  // namespace sculpt::ui
