// SPDX-License-Identifier: Apache-2.0
#include "ui/scene/slice_mouse.h"

namespace sculpt::ui {

namespace {

/// How far a drag across the whole view moves the window or the level: the samples' range.
constexpr double kRangePerView = 1.0;

}  // namespace

bool SliceMouse::handle(SliceViews& slices, const InputEvent& event, double x, double y)
{
    const std::optional<SliceAxis> over = slices.viewAt(x, y);
    if (event.type == EventType::Wheel) {
        if (over) slices.step(*over, event.y);
        return over.has_value();
    }
    if (event.type == EventType::MouseButton && event.press) {
        if (!over) return false;
        mDragged = over;
        mButton = event.button;
        mLastX = x, mLastY = y;
        if (mButton == kLeftButton) slices.setCursor(slices.worldAt(*over, x, y));
        return true;
    }
    if (!mDragged) return false;
    if (event.type == EventType::MouseButton) {
        mDragged.reset();
        return true;
    }
    if (mButton == kLeftButton) {
        slices.setCursor(slices.worldAt(*mDragged, x, y));
    } else {
        const double perPixel = kRangePerView * slices.sampleRange() / slices.rect(*mDragged).width;
        slices.setWindowLevel(slices.window() + (x - mLastX) * perPixel, slices.level() - (y - mLastY) * perPixel);
    }
    mLastX = x, mLastY = y;
    return true;
}

}  // namespace sculpt::ui
