// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file pointer_state.h
/// @brief Where the pointer is and which modifier keys are down, as the events so far say: what
///        a press, a pick and the brush cursor's colour need of the input between events.

namespace sculpt::ui {

struct InputEvent;

class PointerState {
public:
    /// Follows `event`: a move sets the position, a modifier key its bit, a key or a button the
    /// modifiers it came with.
    void track(const InputEvent& event);

    /// Window pixels; negative before the pointer first moved.
    double x() const { return mX; }
    double y() const { return mY; }
    /// The modifier keys held down.
    int held() const { return mHeld; }
    /// The modifiers of the latest key or button: those held and those it reported.
    int current() const { return mCurrent; }
    /// Over a view of `width` x `height` pixels.
    bool inside(int width, int height) const { return mX >= 0 && mY >= 0 && mX < width && mY < height; }

private:
    double mX = -1.0, mY = -1.0;
    int mHeld = 0, mCurrent = 0;
};

}  // namespace sculpt::ui
