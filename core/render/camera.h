// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file camera.h
/// @brief A pinhole camera: where it stands, what it looks at, and the ray through any point of
///        its image.
///
/// Image coordinates: x to the right, y down, in pixels, (0, 0) the top-left corner of the
/// top-left pixel. The field of view is vertical. Camera space: x right, y up, z towards the
/// viewer (the camera looks down -z), as OpenEXR's worldToCamera and most renderers expect.

#include "core/render/surface_extent.h"

#include <openvdb/math/Ray.h>
#include <openvdb/openvdb.h>

namespace sculpt {

struct Camera {
    openvdb::Vec3d position{0.0, 0.0, 10.0};
    openvdb::Vec3d lookAt{0.0};
    openvdb::Vec3d up{0.0, 1.0, 0.0};
    double fovDegrees = 35.0;  ///< vertical field of view

    /// @throws InputError naming the field: non-finite numbers, position == lookAt, up parallel to
    ///         the view direction, a field of view outside (0, 180).
    void validate() const;
    /// The camera turned by `radians` about the vertical axis through lookAt (its up vector):
    /// one frame of a turntable.
    Camera orbited(double radians) const;
    /// World from camera space, row-vector convention (p_world = p_camera * M).
    openvdb::Mat4d worldFromCamera() const;
};

/// A camera that looks at the centre of `extent`'s box from a three-quarter view (front right, a
/// little above; +z is the front, +y up), as near as it can be with every leaf of the extent in
/// view at `aspect` = width / height (with a 10% margin).
Camera framingCamera(const SurfaceExtent& extent, double aspect, double fovDegrees = 35.0);

/// Primary rays of one camera and image size.
class PinholeProjection {
public:
    PinholeProjection(const Camera& camera, int width, int height);
    /// The ray through image point (x, y) in pixels, unit direction (t is world distance).
    openvdb::math::Ray<double> ray(double x, double y) const;

private:
    openvdb::Vec3d mOrigin, mForward, mRight, mUp;
    double mHalfHeight, mHalfWidth;  // of the image plane at distance 1
    double mWidth, mHeight;
};

}  // namespace sculpt
