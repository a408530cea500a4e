// SPDX-License-Identifier: Apache-2.0
#include "ui/input/event_player.h"

namespace sculpt::ui {

namespace {

bool endsFrame(EventType type) { return type != EventType::MouseMove && type != EventType::Wheel; }

}  // namespace

std::vector<InputEvent> EventPlayer::take(double now)
{
    std::vector<InputEvent> batch;
    while (!held() && mNext < mEvents.size() && mEvents[mNext].time <= now - mStart) {
        batch.push_back(mEvents[mNext++]);
        if (endsFrame(batch.back().type)) break;
    }
    return batch;
}

void EventPlayer::resume(double now)
{
    if (!held()) return;
    mStart += now - mHeldSince;
    mHeldSince = -1.0;
}

}  // namespace sculpt::ui
