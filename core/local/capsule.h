// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file capsule.h
/// @brief The points within a distance of a segment: the region a stamp or a stroke step covers.

#include <openvdb/math/Transform.h>

#include <algorithm>

namespace sculpt {

struct Capsule {
    openvdb::Vec3d from{0.0}, to{0.0};  ///< a ball when from == to
    double radius = 0.0;

    static Capsule ball(const openvdb::Vec3d& centre, double radius) { return {centre, centre, radius}; }

    /// Parameter in [0, 1] of the segment point closest to p.
    double closestParameter(const openvdb::Vec3d& p) const
    {
        const openvdb::Vec3d axis = to - from;
        const double length2 = axis.lengthSqr();
        return length2 > 0.0 ? std::clamp((p - from).dot(axis) / length2, 0.0, 1.0) : 0.0;
    }
    openvdb::Vec3d closestPoint(const openvdb::Vec3d& p) const { return from + (to - from) * closestParameter(p); }
    /// Distance from p to the segment (not to the capsule's surface).
    double axisDistance(const openvdb::Vec3d& p) const { return (p - closestPoint(p)).length(); }
    bool contains(const openvdb::Vec3d& p) const { return (p - closestPoint(p)).lengthSqr() <= radius * radius; }

    Capsule grownBy(double margin) const { return {from, to, radius + margin}; }

    /// The same capsule in index space of a uniform linear transform, where a voxel's test is
    /// contains(ijk.asVec3d()): no map call per voxel.
    Capsule inIndexSpace(const openvdb::math::Transform& xform) const
    {
        return {xform.worldToIndex(from), xform.worldToIndex(to), radius / xform.voxelSize()[0]};
    }
};

}  // namespace sculpt
