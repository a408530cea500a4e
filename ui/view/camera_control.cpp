// SPDX-License-Identifier: Apache-2.0
#include "ui/view/camera_control.h"

#include "ui/view/viewport.h"

#include <glm/gtc/matrix_transform.hpp>
#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>

namespace sculpt::ui {

namespace {

constexpr double kDegreesPerPixel = 0.4;
const glm::dvec3 kWorldUp(0.0, 1.0, 0.0);

glm::dvec3 rotate(const glm::dvec3& v, double degrees, const glm::dvec3& axis)
{
    return glm::dvec3(glm::rotate(glm::dmat4(1.0), glm::radians(degrees), axis) * glm::dvec4(v, 0.0));
}

}  // namespace

void CameraControl::get(glm::dvec3& position, glm::dvec3& focal, glm::dvec3& up) const
{
    vtkCamera* c = mViewport.camera();
    c->GetPosition(&position.x);
    c->GetFocalPoint(&focal.x);
    c->GetViewUp(&up.x);
}

void CameraControl::set(const glm::dvec3& position, const glm::dvec3& focal, const glm::dvec3& up)
{
    vtkCamera* c = mViewport.camera();
    c->SetPosition(position.x, position.y, position.z);
    c->SetFocalPoint(focal.x, focal.y, focal.z);
    c->SetViewUp(up.x, up.y, up.z);
    c->OrthogonalizeViewUp();
    mViewport.renderer()->ResetCameraClippingRange();
    ++mMoves;
}

glm::dvec3 CameraControl::focalPoint() const
{
    glm::dvec3 p, f, u;
    get(p, f, u);
    return f;
}

glm::dvec3 CameraControl::eye() const
{
    glm::dvec3 p, f, u;
    get(p, f, u);
    return p;
}

void CameraControl::orbit(double dx, double dy) { orbitDegrees(-dx * kDegreesPerPixel, -dy * kDegreesPerPixel); }

void CameraControl::orbitDegrees(double yaw, double pitch)
{
    glm::dvec3 p, f, u;
    get(p, f, u);
    glm::dvec3 offset = p - f;
    const glm::dvec3 right = glm::normalize(glm::cross(-offset, u));
    const glm::dvec3 yawAxis = trackball ? glm::normalize(u) : kWorldUp * (glm::dot(u, kWorldUp) < 0 ? -1.0 : 1.0);
    offset = rotate(offset, yaw, yawAxis);
    u = rotate(u, yaw, yawAxis);
    const glm::dvec3 pitchAxis = rotate(right, yaw, yawAxis);
    offset = rotate(offset, pitch, pitchAxis);
    u = rotate(u, pitch, pitchAxis);
    set(f + offset, f, u);
}

void CameraControl::pan(double dx, double dy)
{
    glm::dvec3 p, f, u;
    get(p, f, u);
    const double pixel = mViewport.pixelSizeAt(f);
    const glm::dvec3 right = glm::normalize(glm::cross(f - p, u));
    const glm::dvec3 shift = (-dx * right + dy * glm::normalize(u)) * pixel;
    set(p + shift, f + shift, u);
}

void CameraControl::zoomTowards(const glm::dvec3& anchor, double factor)
{
    glm::dvec3 p, f, u;
    get(p, f, u);
    const double keep = 1.0 / factor;  // distances to the anchor scale by this
    const glm::dvec3 newPosition = anchor + (p - anchor) * keep;
    const glm::dvec3 newFocal = f + (newPosition - p);  // same direction, same focal distance...
    const double distance = glm::length(f - p) * keep;  // ...scaled like everything else
    set(newPosition, newPosition + glm::normalize(newFocal - newPosition) * distance, u);
}

void CameraControl::zoom(double factor) { zoomTowards(focalPoint(), factor); }

void CameraControl::frame(const glm::dvec3& lo, const glm::dvec3& hi)
{
    glm::dvec3 p, f, u;
    get(p, f, u);
    const glm::dvec3 centre = 0.5 * (lo + hi);
    // Half the longest side, not the diagonal: a ball fills the view as a sculptor expects.
    const glm::dvec3 size = hi - lo;
    const double radius = std::max(0.55 * std::max({size.x, size.y, size.z}), 1e-6);
    const double halfAngle = glm::radians(mViewport.camera()->GetViewAngle() * 0.5);
    const double aspect = std::min(1.0, double(mViewport.width()) / double(mViewport.height()));
    const double distance = radius / std::sin(std::atan(std::tan(halfAngle) * aspect)) * 1.05;
    glm::dvec3 direction = p - f;
    if (glm::length(direction) == 0.0) direction = glm::dvec3(0, 0, 1);
    set(centre + glm::normalize(direction) * distance, centre, u);
}

void CameraControl::axisView(AxisView view)
{
    glm::dvec3 p, f, u;
    get(p, f, u);
    const double distance = glm::length(p - f);
    glm::dvec3 direction(0, 0, 1), up(0, 1, 0);
    switch (view) {
    case AxisView::Front: break;
    case AxisView::Back: direction = {0, 0, -1}; break;
    case AxisView::Right: direction = {1, 0, 0}; break;
    case AxisView::Left: direction = {-1, 0, 0}; break;
    case AxisView::Top: direction = {0, 1, 0}, up = {0, 0, -1}; break;
    case AxisView::Bottom: direction = {0, -1, 0}, up = {0, 0, 1}; break;
    }
    set(f + direction * distance, f, up);
}

}  // namespace sculpt::ui
