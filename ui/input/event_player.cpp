#include "ui/input/event_player.h"

namespace sculpt::ui {

namespace {

bool endsFrame(EventType type) { return type != EventType::MouseMove && type != EventType::Wheel; }

}  // namespace

std::vector<InputEvent> EventPlayer::take(double elapsed)
{
    std::vector<InputEvent> batch;
    while (mNext < mEvents.size() && mEvents[mNext].time <= elapsed) {
        batch.push_back(mEvents[mNext++]);
        if (endsFrame(batch.back().type)) break;
    }
    return batch;
}

}  // namespace sculpt::ui
