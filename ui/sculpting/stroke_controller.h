// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file stroke_controller.h
/// @brief Turns a mouse drag into a live stroke: each mouse event becomes a sample and its
///        stamps are applied at once (never waiting for a frame: the mesh follows once a frame);
///        the release ends the stroke, one undo step. Pressure comes from the pointer's speed
///        (GLFW has no tablet pressure).

#include "ui/sculpting/brush_options.h"
#include "ui/sculpting/surface_picker.h"

#include <optional>

namespace sculpt {
class Document;
}  // namespace sculpt

namespace sculpt::ui {

class StrokeController {
public:
    bool active() const { return mActive; }

    /// Starts a stroke at a surface hit. @throws InputError (a brush larger than the model).
    void begin(Document& document, const BrushOptions& options, int mods, const SurfaceHit& hit, const Ray& ray,
               double time, double x, double y);
    /// The pointer moved to window (x, y); `hit` is the surface under it, if any. Grab follows
    /// the pointer in the plane through its first hit facing the view, so it never needs a hit.
    /// @return the stamps applied.
    std::size_t move(Document& document, const std::optional<SurfaceHit>& hit, const Ray& ray, double time, double x,
                     double y);
    void end(Document& document);

    /// The pressure of the last sample.
    double pressure() const { return mPressure; }

private:
    double pressureAt(double time, double x, double y);

    bool mActive = false;
    bool mGrab = false;
    bool mFromSpeed = true;
    glm::dvec3 mPlanePoint{0.0}, mPlaneNormal{0.0};
    double mLastTime = 0.0, mLastX = 0.0, mLastY = 0.0;
    double mPressure = 1.0;
};

}  // namespace sculpt::ui
