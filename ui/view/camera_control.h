// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file camera_control.h
/// @brief Navigation as sculptors know it (Blender, SculptGL): orbit about the focal point
///        (turntable about the world's up axis by default, trackball as an option), pan, zoom
///        to the cursor, frame the model, axis views. Camera maths in GLM; VTK's camera stores it.

#include <glm/glm.hpp>

#include <cstdint>

namespace sculpt::ui {

class Viewport;

enum class AxisView { Front, Back, Right, Left, Top, Bottom };

class CameraControl {
public:
    explicit CameraControl(Viewport& viewport) : mViewport(viewport) {}

    bool trackball = false;  ///< false: turntable (the world's +y stays up)

    /// Orbit by a mouse motion of (dx, dy) pixels.
    void orbit(double dx, double dy);
    /// Orbit by angles, degrees (keys).
    void orbitDegrees(double yaw, double pitch);
    /// Moves the view so the scene follows a mouse motion of (dx, dy) pixels.
    void pan(double dx, double dy);
    /// Moves towards `anchor` (the point under the cursor) by `factor` (> 1: closer), keeping
    /// the anchor where it is on screen.
    void zoomTowards(const glm::dvec3& anchor, double factor);
    /// Zooms about the view's centre.
    void zoom(double factor);
    /// Looks at the box [lo, hi] so all of it is in view, keeping the view direction.
    void frame(const glm::dvec3& lo, const glm::dvec3& hi);
    /// Looks along an axis at the current focal point.
    void axisView(AxisView view);

    glm::dvec3 focalPoint() const;
    glm::dvec3 eye() const;
    /// Counts every change of the camera, whatever made it (drag, keys, wheel, frame, axis
    /// views): the display's level of detail follows it.
    std::uint64_t moves() const { return mMoves; }

private:
    void set(const glm::dvec3& position, const glm::dvec3& focal, const glm::dvec3& up);
    void get(glm::dvec3& position, glm::dvec3& focal, glm::dvec3& up) const;

    Viewport& mViewport;
    std::uint64_t mMoves = 0;
};

}  // namespace sculpt::ui
