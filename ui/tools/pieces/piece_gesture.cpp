// SPDX-License-Identifier: Apache-2.0
#include "ui/tools/pieces/piece_gesture.h"

#include "core/base/text_format.h"

#include <GLFW/glfw3.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <cstdlib>

namespace sculpt::ui {

namespace {

constexpr double kPi = 3.14159265358979323846;

openvdb::Vec3d vdb(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

/// Pointer angle about the pivot on screen, counter-clockwise as seen (window y runs down).
double screenAngle(const glm::dvec3& pivotPixel, double x, double y)
{
    return std::atan2(-(y - pivotPixel.y), x - pivotPixel.x);
}

double screenDistance(const glm::dvec3& pivotPixel, double x, double y)
{
    return std::hypot(x - pivotPixel.x, y - pivotPixel.y);
}

/// p -> p about `pivot` by `m` (row vectors): translate the pivot to the origin, m, and back.
openvdb::Mat4d aboutPivot(const openvdb::Mat4d& m, const glm::dvec3& pivot)
{
    openvdb::Mat4d to, back;
    to.setToTranslation(-vdb(pivot));
    back.setToTranslation(vdb(pivot));
    return to * m * back;
}

}  // namespace

PieceGesture::PieceGesture(Kind kind, const openvdb::Mat4d& start, const glm::dvec3& pivot, const Viewport& view,
                           const glm::dvec3& viewDirection, double x, double y)
    : mKind(kind), mStart(start), mPivot(pivot), mViewDirection(viewDirection), mStartX(x), mStartY(y)
{
    mStartPoint = onViewPlane(view, x, y);
    mPivotPixel = view.project(pivot);
}

glm::dvec3 PieceGesture::onViewPlane(const Viewport& view, double x, double y) const
{
    const Ray ray = view.rayThrough(x, y);
    const double along = glm::dot(ray.direction, mViewDirection);
    if (std::abs(along) < 1e-9) return mPivot;
    return ray.origin + ray.direction * (glm::dot(mPivot - ray.origin, mViewDirection) / along);
}

glm::dvec3 PieceGesture::axisVector() const
{
    glm::dvec3 axis(0.0);
    axis[mAxis < 0 ? 0 : mAxis] = 1.0;
    return axis;
}

bool PieceGesture::typedValue(double& value) const
{
    if (mTyped.empty()) return false;
    char* end = nullptr;
    value = std::strtod(mTyped.c_str(), &end);
    return end == mTyped.c_str() + mTyped.size() && std::isfinite(value);
}

void PieceGesture::point(const Viewport& view, double x, double y)
{
    double typed = 0.0;
    const bool hasTyped = typedValue(typed);
    switch (mKind) {
    case Kind::Move: {
        const glm::dvec3 move = onViewPlane(view, x, y) - mStartPoint;
        mMove = hasTyped ? typed * axisVector() : mAxis < 0 ? move : glm::dot(move, axisVector()) * axisVector();
        break;
    }
    case Kind::Rotate:
        mAngle = hasTyped ? typed * kPi / 180.0
                          : screenAngle(mPivotPixel, x, y) - screenAngle(mPivotPixel, mStartX, mStartY);
        break;
    case Kind::Scale: {
        const double from = screenDistance(mPivotPixel, mStartX, mStartY);
        mFactor = hasTyped && typed > 0.0 ? typed : from > 1.0 ? screenDistance(mPivotPixel, x, y) / from : 1.0;
        mFactor = std::max(mFactor, 1e-3);
        break;
    }
    }
}

bool PieceGesture::key(int glfwKey)
{
    if (glfwKey >= GLFW_KEY_X && glfwKey <= GLFW_KEY_Z) {
        if (mKind == Kind::Scale) return true;  // a piece scales uniformly: its voxels stay cubes
        const int axis = glfwKey - GLFW_KEY_X;
        mAxis = mAxis == axis ? -1 : axis;
    } else if (glfwKey >= GLFW_KEY_0 && glfwKey <= GLFW_KEY_9) {
        mTyped += char('0' + glfwKey - GLFW_KEY_0);
    } else if (glfwKey >= GLFW_KEY_KP_0 && glfwKey <= GLFW_KEY_KP_9) {
        mTyped += char('0' + glfwKey - GLFW_KEY_KP_0);
    } else if (glfwKey == GLFW_KEY_PERIOD || glfwKey == GLFW_KEY_KP_DECIMAL) {
        mTyped += '.';
    } else if (glfwKey == GLFW_KEY_MINUS || glfwKey == GLFW_KEY_KP_SUBTRACT) {
        mTyped = mTyped.rfind('-', 0) == 0 ? mTyped.substr(1) : "-" + mTyped;
    } else if (glfwKey == GLFW_KEY_BACKSPACE) {
        if (!mTyped.empty()) mTyped.pop_back();
    } else {
        return false;
    }
    return true;
}

openvdb::Mat4d PieceGesture::placementAt(double t) const
{
    openvdb::Mat4d m = openvdb::Mat4d::identity();
    switch (mKind) {
    case Kind::Move: m.setToTranslation(vdb(t * mMove)); break;
    case Kind::Rotate: {
        // About the held axis, else the line of sight; turned as the pointer turns on screen.
        const glm::dvec3 axis =
            mAxis < 0 ? -mViewDirection : axisVector() * (glm::dot(axisVector(), mViewDirection) > 0.0 ? -1.0 : 1.0);
        m.setToRotation(vdb(axis), -t * mAngle);
        m = aboutPivot(m, mPivot);
        break;
    }
    case Kind::Scale:
        m.setToScale(openvdb::Vec3d(std::pow(mFactor, t)));
        m = aboutPivot(m, mPivot);
        break;
    }
    return mStart * m;
}

std::string PieceGesture::describe(const std::string& units) const
{
    static const char* kAxes[] = {"X", "Y", "Z"};
    std::string text = mKind == Kind::Move ? "Move" : mKind == Kind::Rotate ? "Rotate" : "Scale";
    if (mAxis >= 0) text += std::string(mKind == Kind::Move ? " along " : " about ") + kAxes[mAxis];
    switch (mKind) {
    case Kind::Move: text += ": " + formatNumber(glm::length(mMove)) + " " + units; break;
    case Kind::Rotate: text += ": " + formatNumber(mAngle * 180.0 / kPi) + " degrees"; break;
    case Kind::Scale: text += ": x" + formatNumber(mFactor); break;
    }
    if (!mTyped.empty()) text += " [" + mTyped + "]";
    return text + "  (X/Y/Z axis, type a value; click or Enter keeps, Esc or right click drops)";
}

}  // namespace sculpt::ui
