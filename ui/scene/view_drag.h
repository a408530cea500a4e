// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file view_drag.h
/// @brief A drag that is not the tool's: the camera's (orbit, pan, zoom), a brush setting's (F
///        sizes the brush, Shift+F sets its strength: the pointer moves, a click keeps, Esc
///        restores) or the open mode's handle.

#include "ui/sculpting/brush_options.h"
#include "ui/view/camera_control.h"

#include <string>

namespace sculpt::ui {

class ViewDrag {
public:
    enum class Kind { None, Orbit, Pan, Zoom, Radius, Strength, Mode };

    Kind kind() const { return mKind; }
    bool active() const { return mKind != Kind::None; }
    /// A brush setting follows the pointer (it lasts past the button's release, to a click or a key).
    bool adjusting() const { return mKind == Kind::Radius || mKind == Kind::Strength; }

    /// A press that is not the tool's moves the camera: Shift pans, Ctrl zooms, else it orbits.
    void grabCamera(int mods);
    /// The open mode took the press: its handle follows.
    void grabHandle() { mKind = Kind::Mode; }
    /// F (Radius) or Shift+F (Strength): the setting follows the pointer from `x` on.
    void adjust(Kind setting, double x, const BrushOptions& brush);
    /// The pointer moved by (dx, dy) to x: the camera or the brush setting follows (not below
    /// `minRadius`); a mode's handle is its mode's.
    void follow(double x, double dx, double dy, CameraControl& camera, BrushOptions& brush, double minRadius) const;
    /// A button let go: a camera or handle drag ends; an adjustment goes on.
    void release();
    /// Ends the drag; `restore` (Esc): an adjusted setting goes back to what it was.
    void end(bool restore, BrushOptions& brush);
    /// What the tooltip says while a setting is adjusted, else "".
    std::string hint(const BrushOptions& brush) const;

private:
    Kind mKind = Kind::None;
    double mStartX = 0.0, mStartValue = 0.0;
};

}  // namespace sculpt::ui
