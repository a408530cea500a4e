// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file skeleton.h
/// @brief The convex skeletons a primitive's field is built around: point, segment, triangle,
///        box. Each gives the exact Euclidean distance from a point to itself.

#include <openvdb/openvdb.h>

#include <array>
#include <string>

namespace sculpt {

enum class SkeletonType { Point, Segment, Triangle, Box };

struct Skeleton {
    SkeletonType type = SkeletonType::Point;
    /// Point: [0]; segment: [0]-[1]; triangle: [0], [1], [2]; box: [0] the centre.
    std::array<openvdb::Vec3d, 3> points{};
    openvdb::Vec3d halfExtents{0.0};                           ///< box only
    openvdb::Mat3d worldFromBox = openvdb::Mat3d::identity();  ///< box orientation (rotation)

    /// Distance from `p` to the skeleton (0 inside a box).
    double distance(const openvdb::Vec3d& p) const;
    /// World box containing the skeleton.
    openvdb::BBoxd bounds() const;
    /// @throws InputError (message naming `what`) for degenerate segments or triangles, or boxes
    ///         with non-positive extents.
    void validate(const std::string& what) const;
};

/// "point", "segment", "triangle", "box". @throws InputError for other names.
SkeletonType skeletonFromName(const std::string& name);

}  // namespace sculpt
