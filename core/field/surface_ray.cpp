#include "core/field/surface_ray.h"

#include <algorithm>
#include <cmath>

namespace sculpt {

namespace {

constexpr double kStepOfDistance = 0.5;  // of |phi|: safe for the trilinear field's slope
constexpr double kMinStepVoxels = 0.1;
constexpr int kBisections = 20;  // 2^-20 of a step: far below a voxel

/// [t0, t1] of the ray o + t d inside the box, if it meets it at t >= 0.
std::optional<std::pair<double, double>> clip(const openvdb::BBoxd& box, const openvdb::Vec3d& o,
                                              const openvdb::Vec3d& d)
{
    double t0 = 0.0, t1 = std::numeric_limits<double>::max();
    for (int axis = 0; axis < 3; ++axis) {
        if (d[axis] == 0.0) {
            if (o[axis] < box.min()[axis] || o[axis] > box.max()[axis]) return std::nullopt;
            continue;
        }
        double a = (box.min()[axis] - o[axis]) / d[axis], b = (box.max()[axis] - o[axis]) / d[axis];
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
    }
    if (t0 > t1) return std::nullopt;
    return std::make_pair(t0, t1);
}

}  // namespace

std::optional<RayCrossing> firstSurfaceCrossing(const PreEditField& field, const openvdb::CoordBBox& box,
                                                const openvdb::Vec3d& originWorld, const openvdb::Vec3d& directionWorld)
{
    if (box.empty() || !originWorld.isFinite() || !directionWorld.isFinite()) return std::nullopt;
    const openvdb::math::Transform& xform = field.field().grid().transform();
    const openvdb::Vec3d o = xform.worldToIndex(originWorld);
    openvdb::Vec3d d = xform.worldToIndex(originWorld + directionWorld) - o;
    if (!(d.length() > 0.0)) return std::nullopt;
    d.normalize();
    // A voxel more on each side: the trilinear field reaches past the last voxel's centre.
    const openvdb::BBoxd searched(box.min().asVec3d() - openvdb::Vec3d(1.0), box.max().asVec3d() + openvdb::Vec3d(1.0));
    const auto span = clip(searched, o, d);
    if (!span) return std::nullopt;
    const double h = field.field().voxelSize();
    auto phiAt = [&](double t) { return field.sample(o + d * t) / h; };  // in voxels

    double t = span->first, phi = phiAt(t);
    while (t < span->second) {
        const double next = std::min(span->second, t + std::max(kStepOfDistance * std::abs(phi), kMinStepVoxels));
        const double phiNext = phiAt(next);
        if ((phi > 0.0) != (phiNext > 0.0)) {
            double lo = t, hi = next;  // phi(lo) on the side phi started, phi(hi) across
            for (int i = 0; i < kBisections; ++i) {
                const double mid = 0.5 * (lo + hi);
                ((phiAt(mid) > 0.0) == (phi > 0.0) ? lo : hi) = mid;
            }
            const openvdb::Vec3d hit = o + d * (0.5 * (lo + hi));
            const openvdb::Vec3d position = xform.indexToWorld(hit);
            // Voxels are cubes (a rotation and one scale): a direction maps as a point does.
            const openvdb::Vec3d g = field.gradient(hit);
            const openvdb::Vec3d normal = xform.indexToWorld(hit + (g.length() > 0.0 ? g : -d)) - position;
            return RayCrossing{position, normal.unit()};
        }
        t = next, phi = phiNext;
    }
    return std::nullopt;
}

}  // namespace sculpt
