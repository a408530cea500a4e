// SPDX-License-Identifier: Apache-2.0
#include "ui/scene/view_drag.h"

#include "ui/input/input_event.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace sculpt::ui {

void ViewDrag::grabCamera(int mods)
{
    // Navigation: middle (Blender), right (SculptGL), Alt+left (touchpads), left off the model.
    mKind = (mods & kShift) ? Kind::Pan : (mods & kControl) ? Kind::Zoom : Kind::Orbit;
}

void ViewDrag::adjust(Kind setting, double x, const BrushOptions& brush)
{
    mKind = setting;
    mStartX = x;
    mStartValue = setting == Kind::Radius ? brush.radius : brush.strength;
}

void ViewDrag::follow(double x, double dx, double dy, CameraControl& camera, BrushOptions& brush,
                      double minRadius) const
{
    switch (mKind) {
    case Kind::Orbit: camera.orbit(dx, dy); break;
    case Kind::Pan: camera.pan(dx, dy); break;
    case Kind::Zoom: camera.zoom(std::pow(1.01, -dy)); break;
    case Kind::Radius: brush.radius = std::max(minRadius, mStartValue * std::pow(2.0, (x - mStartX) / 120.0)); break;
    case Kind::Strength: brush.strength = std::clamp(mStartValue + (x - mStartX) / 300.0, 0.01, 1.0); break;
    case Kind::Mode:
    case Kind::None: break;
    }
}

void ViewDrag::release()
{
    if (!adjusting()) mKind = Kind::None;
}

void ViewDrag::end(bool restore, BrushOptions& brush)
{
    if (restore && adjusting()) (mKind == Kind::Radius ? brush.radius : brush.strength) = mStartValue;
    mKind = Kind::None;
}

std::string ViewDrag::hint(const BrushOptions& brush) const
{
    char text[96] = "";
    if (mKind == Kind::Radius)
        std::snprintf(text, sizeof text, "radius %.3g (move, click to keep, Esc to cancel)", brush.radius);
    if (mKind == Kind::Strength)
        std::snprintf(text, sizeof text, "strength %.2f (move, click to keep, Esc to cancel)", brush.strength);
    return text;
}

}  // namespace sculpt::ui
