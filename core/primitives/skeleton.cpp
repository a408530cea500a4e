// SPDX-License-Identifier: Apache-2.0
#include "core/primitives/skeleton.h"

#include "core/base/enum_names.h"

#include <algorithm>
#include <cmath>

namespace sculpt {

namespace {

using Vec = openvdb::Vec3d;

constexpr EnumNames<SkeletonType, 4> kSkeletonNames{{{SkeletonType::Point, "point"},
                                                     {SkeletonType::Segment, "segment"},
                                                     {SkeletonType::Triangle, "triangle"},
                                                     {SkeletonType::Box, "box"}}};

double segmentDistance(const Vec& p, const Vec& a, const Vec& b)
{
    const Vec ab = b - a;
    const double t = std::clamp((p - a).dot(ab) / ab.lengthSqr(), 0.0, 1.0);
    return (p - (a + ab * t)).length();
}

/// Closest point on a triangle (Ericson, Real-Time Collision Detection, 5.1.5).
double triangleDistance(const Vec& p, const Vec& a, const Vec& b, const Vec& c)
{
    const Vec ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0) return ap.length();
    const Vec bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3) return bp.length();
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + ab * (d1 / (d1 - d3)))).length();
    const Vec cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6) return cp.length();
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + ac * (d2 / (d2 - d6)))).length();
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
        return (p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))))).length();
    }
    const double denom = 1.0 / (va + vb + vc);
    return (p - (a + ab * (vb * denom) + ac * (vc * denom))).length();
}

double boxDistance(const Vec& p, const Skeleton& s)
{
    // Into box axes: worldFromBox is a rotation, its transpose the inverse.
    const Vec local = s.worldFromBox.transpose() * (p - s.points[0]);
    Vec outside;
    for (int i = 0; i < 3; ++i) outside[i] = std::max(std::abs(local[i]) - s.halfExtents[i], 0.0);
    return outside.length();
}

}  // namespace

double Skeleton::distance(const openvdb::Vec3d& p) const
{
    switch (type) {
    case SkeletonType::Point: return (p - points[0]).length();
    case SkeletonType::Segment: return segmentDistance(p, points[0], points[1]);
    case SkeletonType::Triangle: return triangleDistance(p, points[0], points[1], points[2]);
    case SkeletonType::Box: return boxDistance(p, *this);
    }
    return 0.0;
}

openvdb::BBoxd Skeleton::bounds() const
{
    openvdb::BBoxd box;
    switch (type) {
    case SkeletonType::Point: box.expand(points[0]); break;
    case SkeletonType::Segment:
        box.expand(points[0]);
        box.expand(points[1]);
        break;
    case SkeletonType::Triangle:
        for (const auto& q : points) box.expand(q);
        break;
    case SkeletonType::Box:
        for (int corner = 0; corner < 8; ++corner) {
            const Vec local((corner & 1 ? 1 : -1) * halfExtents[0], (corner & 2 ? 1 : -1) * halfExtents[1],
                            (corner & 4 ? 1 : -1) * halfExtents[2]);
            box.expand(points[0] + worldFromBox * local);
        }
        break;
    }
    return box;
}

void Skeleton::validate(const std::string& what) const
{
    for (const auto& q : points) {
        if (!std::isfinite(q.lengthSqr())) throw InputError(what + ": coordinates must be finite numbers");
    }
    if (type == SkeletonType::Segment && (points[1] - points[0]).lengthSqr() < 1e-20) {
        throw InputError(what + ": degenerate segment (its two ends coincide)");
    }
    if (type == SkeletonType::Triangle && (points[1] - points[0]).cross(points[2] - points[0]).lengthSqr() < 1e-20) {
        throw InputError(what + ": degenerate triangle (its corners are collinear)");
    }
    if (type == SkeletonType::Box && !(halfExtents.x() > 0 && halfExtents.y() > 0 && halfExtents.z() > 0 &&
                                       std::isfinite(halfExtents.lengthSqr()))) {
        throw InputError(what + ": box half extents must be positive numbers");
    }
}

SkeletonType skeletonFromName(const std::string& name) { return enumFromName(kSkeletonNames, name, "skeleton"); }

}  // namespace sculpt
