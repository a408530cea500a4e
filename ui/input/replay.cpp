// SPDX-License-Identifier: Apache-2.0
#include "ui/input/replay.h"

namespace sculpt::ui {

Replay::Replay(const std::filesystem::path& play, std::filesystem::path record) : mRecordTo(std::move(record))
{
    if (!play.empty()) mPlayer = std::make_unique<EventPlayer>(readInputEvents(play.string()));
}

void Replay::note(const InputEvent& event)
{
    switch (event.type) {
    case EventType::Screenshot:
    case EventType::Report: mAsked.push_back(event); break;
    case EventType::WaitForJob:
    case EventType::Fault: break;  // a script's, not a user's
    default:
        if (!mRecordTo.empty()) mRecording.push_back(event);
        break;
    }
}

void Replay::askScreenshot(const std::filesystem::path& path)
{
    InputEvent screenshot;
    screenshot.type = EventType::Screenshot;
    screenshot.text = path.string();
    mAsked.push_back(screenshot);
}

void Replay::save() const
{
    if (!mRecordTo.empty()) writeInputEvents(mRecording, mRecordTo.string());
}

}  // namespace sculpt::ui
