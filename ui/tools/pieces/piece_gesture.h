// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file piece_gesture.h
/// @brief Blender's G, R and S on a piece: the pointer moves, turns or scales it about its
///        centre until a click (or Enter) keeps it and Esc (or a right click) drops it; X, Y or Z
///        holds it to that world axis, and a typed number sets the amount (a length, degrees, a
///        factor). Only the placement changes, never a voxel.

#include "ui/view/viewport.h"

#include <glm/vec3.hpp>
#include <openvdb/Types.h>

#include <string>

namespace sculpt::ui {

class PieceGesture {
public:
    enum class Kind { Move, Rotate, Scale };

    /// Starts at the pointer (x, y) on a piece placed at `start` whose centre is `pivot` (world),
    /// seen along `viewDirection` (unit, from the eye).
    PieceGesture(Kind kind, const openvdb::Mat4d& start, const glm::dvec3& pivot, const Viewport& view,
                 const glm::dvec3& viewDirection, double x, double y);

    /// The pointer is at (x, y) now.
    void point(const Viewport& view, double x, double y);
    /// X, Y, Z (again: free), digits, '.', '-' and Backspace. @return false for any other key.
    bool key(int glfwKey);

    /// The placement the gesture gives at fraction t of it (0: where it began, 1: now).
    openvdb::Mat4d placementAt(double t) const;
    Kind kind() const { return mKind; }
    /// The status line: "Move along X: 12.5 mm (type a value, Enter keeps, Esc drops)".
    std::string describe(const std::string& units) const;

private:
    glm::dvec3 onViewPlane(const Viewport& view, double x, double y) const;
    glm::dvec3 axisVector() const;
    /// The typed value, if one was typed and reads as a number.
    bool typedValue(double& value) const;

    Kind mKind;
    openvdb::Mat4d mStart;
    glm::dvec3 mPivot, mViewDirection;
    glm::dvec3 mStartPoint;              // the pointer's start on the view plane through the pivot
    double mStartX, mStartY;             // ... and on screen
    glm::dvec3 mPivotPixel{0.0};         // the pivot on screen
    glm::dvec3 mMove{0.0};               // Move: the translation, world
    double mAngle = 0.0, mFactor = 1.0;  // Rotate: radians about the axis; Scale: the factor
    int mAxis = -1;                      // 0, 1, 2: held to that world axis
    std::string mTyped;
};

}  // namespace sculpt::ui
