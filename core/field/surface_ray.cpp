// SPDX-License-Identifier: Apache-2.0
#include "core/field/surface_ray.h"

#include <openvdb/math/Ray.h>

#include <algorithm>
#include <cmath>

namespace sculpt {

namespace {

constexpr double kStepOfDistance = 0.5;  // of |phi|: safe for the trilinear field's slope
constexpr double kMinStepVoxels = 0.1;
constexpr int kBisections = 20;  // 2^-20 of a step: far below a voxel

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
    openvdb::math::Ray<double> ray(o, d, 0.0);
    if (!ray.clip(searched)) return std::nullopt;
    const double h = field.field().voxelSize();
    auto phiAt = [&](double t) { return field.sample(o + d * t) / h; };  // in voxels

    double t = ray.t0(), phi = phiAt(t);
    while (t < ray.t1()) {
        const double next = std::min(ray.t1(), t + std::max(kStepOfDistance * std::abs(phi), kMinStepVoxels));
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
