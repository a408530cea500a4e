// SPDX-License-Identifier: Apache-2.0
#include "ui/input/pointer_state.h"

#include "ui/input/input_event.h"

namespace sculpt::ui {

void PointerState::track(const InputEvent& event)
{
    switch (event.type) {
    case EventType::MouseMove: mX = event.x, mY = event.y; break;
    case EventType::MouseButton: mCurrent = mHeld | event.mods; break;
    case EventType::Key: {
        const int bit = modifierOfKey(event.key);
        if (bit) mHeld = event.press ? (mHeld | bit) : (mHeld & ~bit);
        mCurrent = mHeld | (event.press ? event.mods : 0);
        break;
    }
    default: break;
    }
}

}  // namespace sculpt::ui
