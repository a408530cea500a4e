// SPDX-License-Identifier: Apache-2.0
#include "ui/sculpting/stroke_controller.h"

#include "sculpt/session/document.h"

#include <algorithm>
#include <cmath>

namespace sculpt::ui {

namespace {

/// Pointer speed (pixels per second) at which the pressure falls to its lightest.
constexpr double kFastSpeed = 2500.0;
constexpr double kLightestPressure = 0.35;

StrokeSample sampleAt(const glm::dvec3& p, double pressure, const Ray& ray)
{
    return {openvdb::Vec3d(p.x, p.y, p.z), pressure, openvdb::Vec3d(ray.direction.x, ray.direction.y, ray.direction.z)};
}

}  // namespace

double StrokeController::pressureAt(double time, double x, double y)
{
    const double dt = time - mLastTime;
    if (mFromSpeed && dt > 1e-4) {
        const double speed = std::hypot(x - mLastX, y - mLastY) / dt;
        const double target = std::max(kLightestPressure, 1.0 - (1.0 - kLightestPressure) * speed / kFastSpeed);
        mPressure = 0.6 * mPressure + 0.4 * target;  // smoothed: event timing is jittery
    }
    mLastTime = time, mLastX = x, mLastY = y;
    return mPressure;
}

void StrokeController::begin(Document& document, const BrushOptions& options, int mods, const SurfaceHit& hit,
                             const Ray& ray, double time, double x, double y)
{
    const Stroke settings = strokeSettings(options, mods);
    document.beginStroke(settings, strokeSources(options, mods), options.stopAtPieces);
    mActive = true;
    mGrab = settings.brush.tool == BrushTool::Grab;
    mFromSpeed = options.pressureFromSpeed;
    mPlanePoint = hit.position;
    mPlaneNormal = -ray.direction;
    mPressure = 1.0;
    mLastTime = time, mLastX = x, mLastY = y;
    document.extendStroke(sampleAt(hit.position, mPressure, ray));
}

std::size_t StrokeController::move(Document& document, const std::optional<SurfaceHit>& hit, const Ray& ray,
                                   double time, double x, double y)
{
    if (!mActive) return 0;
    glm::dvec3 point;
    if (mGrab) {
        const double along = glm::dot(mPlaneNormal, ray.direction);
        if (std::abs(along) < 1e-9) return 0;
        point = ray.origin + ray.direction * (glm::dot(mPlanePoint - ray.origin, mPlaneNormal) / along);
    } else if (hit) {
        point = hit->position;
    } else {
        return 0;  // off the model: the stroke resumes where the pointer comes back
    }
    return document.extendStroke(sampleAt(point, pressureAt(time, x, y), ray)).stamps;
}

void StrokeController::end(Document& document)
{
    if (!mActive) return;
    mActive = false;
    document.endStroke();
}

}  // namespace sculpt::ui
