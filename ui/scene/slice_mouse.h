// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file slice_mouse.h
/// @brief The mouse over the Slices view (SliceViews): a left press or drag puts the cursor
///        there, a right drag sets the window (across) and the level (up and down), as scan
///        viewers do, the wheel steps through the slices.

#include "ui/input/input_event.h"
#include "ui/view/slice_views.h"

#include <optional>

namespace sculpt::ui {

class SliceMouse {
public:
    /// Whether `event`, with the pointer at (x, y), was the slices' (then nothing else takes it).
    bool handle(SliceViews& slices, const InputEvent& event, double x, double y);
    bool dragging() const { return mDragged.has_value(); }

private:
    std::optional<SliceAxis> mDragged;  // the view a button went down in
    int mButton = kLeftButton;
    double mLastX = 0.0, mLastY = 0.0;
};

}  // namespace sculpt::ui
