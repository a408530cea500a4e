// SPDX-License-Identifier: Apache-2.0
#include "core/render/camera.h"

#include "core/base/errors.h"
#include "core/base/text_format.h"

#include <algorithm>
#include <cmath>

namespace sculpt {

namespace {

using openvdb::Vec3d;

constexpr double kDegrees = M_PI / 180.0;

struct Basis {
    Vec3d forward, right, up;
};

Basis basisOf(const Camera& camera)
{
    Basis b;
    b.forward = (camera.lookAt - camera.position).unitSafe();
    b.right = b.forward.cross(camera.up).unitSafe();
    b.up = b.right.cross(b.forward);
    return b;
}

}  // namespace

void Camera::validate() const
{
    if (!position.isFinite() || !lookAt.isFinite() || !up.isFinite() || !std::isfinite(fovDegrees)) {
        throw InputError("camera: position, look-at, up and field of view must be finite numbers");
    }
    const Vec3d view = lookAt - position;
    if (!(view.length() > 0.0)) throw InputError("camera: the position and the look-at point coincide");
    if (!(up.length() > 0.0) || view.unit().cross(up.unit()).length() < 1e-6) {
        throw InputError("camera: the up vector is parallel to the view direction");
    }
    if (!(fovDegrees > 0.0 && fovDegrees < 180.0)) {
        throw InputError("camera: field of view must be between 0 and 180 degrees (got " + formatNumber(fovDegrees) +
                         ")");
    }
}

Camera Camera::orbited(double radians) const
{
    const Vec3d axis = up.unitSafe();
    const Vec3d offset = position - lookAt;
    // Rodrigues' rotation of the offset about the up axis.
    const Vec3d turned = offset * std::cos(radians) + axis.cross(offset) * std::sin(radians) +
                         axis * (axis.dot(offset) * (1.0 - std::cos(radians)));
    Camera c = *this;
    c.position = lookAt + turned;
    return c;
}

openvdb::Mat4d Camera::worldFromCamera() const
{
    const Basis b = basisOf(*this);
    openvdb::Mat4d m = openvdb::Mat4d::identity();
    for (int a = 0; a < 3; ++a) {
        m[0][a] = b.right[a];
        m[1][a] = b.up[a];
        m[2][a] = -b.forward[a];
        m[3][a] = position[a];
    }
    return m;
}

Camera framingCamera(const SurfaceExtent& extent, double aspect, double fovDegrees)
{
    Camera camera;
    camera.fovDegrees = fovDegrees;
    camera.lookAt = extent.bounds.getCenter();
    const Vec3d towardsCamera = Vec3d(0.55, 0.35, 1.0).unit();
    camera.position = camera.lookAt + towardsCamera;
    const Basis b = basisOf(camera);
    // The nearest distance at which every point (with its pad) is inside the view, with a margin.
    const double tanVertical = 0.9 * std::tan(0.5 * fovDegrees * kDegrees), tanHorizontal = tanVertical * aspect;
    double distance = 1e-6;
    for (const Vec3d& p : extent.leafCentres) {
        const Vec3d d = p - camera.lookAt;
        const double depth = d.dot(towardsCamera) + extent.padWorld;  // towards the camera: nearer
        distance = std::max({distance, depth + (std::abs(d.dot(b.right)) + extent.padWorld) / tanHorizontal,
                             depth + (std::abs(d.dot(b.up)) + extent.padWorld) / tanVertical});
    }
    camera.position = camera.lookAt + towardsCamera * distance;
    return camera;
}

PinholeProjection::PinholeProjection(const Camera& camera, int width, int height)
    : mOrigin(camera.position), mWidth(width), mHeight(height)
{
    const Basis b = basisOf(camera);
    mForward = b.forward;
    mRight = b.right;
    mUp = b.up;
    mHalfHeight = std::tan(0.5 * camera.fovDegrees * kDegrees);
    mHalfWidth = mHalfHeight * mWidth / mHeight;
}

openvdb::math::Ray<double> PinholeProjection::ray(double x, double y) const
{
    const double u = (2.0 * x / mWidth - 1.0) * mHalfWidth;
    const double v = (1.0 - 2.0 * y / mHeight) * mHalfHeight;
    return openvdb::math::Ray<double>(mOrigin, (mForward + mRight * u + mUp * v).unit());
}

}  // namespace sculpt
