// SPDX-License-Identifier: Apache-2.0
#include "core/primitives/analytic_shapes.h"

#include "core/base/errors.h"
#include "core/base/text_format.h"

#include <boost/math/constants/constants.hpp>

#include <algorithm>
#include <cmath>

namespace sculpt {

namespace {

constexpr double kPi = boost::math::constants::pi<double>();

void requirePositive(double value, const char* field)
{
    if (!(value > 0.0) || !std::isfinite(value)) {
        throw InputError(std::string(field) + " must be a positive number (got " + formatNumber(value) + ")");
    }
}

openvdb::BBoxd centredBox(double halfExtent)
{
    return openvdb::BBoxd(openvdb::Vec3d(-halfExtent), openvdb::Vec3d(halfExtent));
}

}  // namespace

AnalyticSdf sphereSdf(double radiusWorld)
{
    requirePositive(radiusWorld, "radius");
    return {[radiusWorld](const openvdb::Vec3d& p) { return p.length() - radiusWorld; }, centredBox(radiusWorld),
            4.0 * kPi * radiusWorld * radiusWorld, "sphere of radius " + formatNumber(radiusWorld)};
}

AnalyticSdf boxSdf(double halfSideWorld)
{
    requirePositive(halfSideWorld, "half side");
    const double a = halfSideWorld;
    auto distance = [a](const openvdb::Vec3d& p) {
        const openvdb::Vec3d q(std::abs(p.x()) - a, std::abs(p.y()) - a, std::abs(p.z()) - a);
        const openvdb::Vec3d outside(std::max(q.x(), 0.0), std::max(q.y(), 0.0), std::max(q.z(), 0.0));
        return outside.length() + std::min(std::max({q.x(), q.y(), q.z()}), 0.0);
    };
    return {distance, centredBox(a), 24.0 * a * a, "box of half side " + formatNumber(a)};
}

AnalyticSdf torusSdf(double majorRadiusWorld, double minorRadiusWorld)
{
    requirePositive(majorRadiusWorld, "major radius");
    requirePositive(minorRadiusWorld, "minor radius");
    if (!(minorRadiusWorld < majorRadiusWorld)) {
        throw InputError("minor radius (" + formatNumber(minorRadiusWorld) +
                         ") must be smaller than the major radius (" + formatNumber(majorRadiusWorld) + ")");
    }
    const double R = majorRadiusWorld, r = minorRadiusWorld;
    auto distance = [R, r](const openvdb::Vec3d& p) {
        const double ring = std::hypot(p.x(), p.y()) - R;
        return std::hypot(ring, p.z()) - r;
    };
    const openvdb::BBoxd bounds(openvdb::Vec3d(-(R + r), -(R + r), -r), openvdb::Vec3d(R + r, R + r, r));
    return {distance, bounds, 4.0 * kPi * kPi * R * r, "torus of radii " + formatNumber(R) + " and " + formatNumber(r)};
}

FieldImage makeSphere(double radiusWorld, double voxelSize, double halfWidthVoxels)
{
    return rasterizeSdf(sphereSdf(radiusWorld), voxelSize, halfWidthVoxels);
}

FieldImage makeBox(double halfSideWorld, double voxelSize, double halfWidthVoxels)
{
    return rasterizeSdf(boxSdf(halfSideWorld), voxelSize, halfWidthVoxels);
}

FieldImage makeTorus(double majorRadiusWorld, double minorRadiusWorld, double voxelSize, double halfWidthVoxels)
{
    return rasterizeSdf(torusSdf(majorRadiusWorld, minorRadiusWorld), voxelSize, halfWidthVoxels);
}

AnalyticSdf startingShapeSdf(const std::string& name, double size, double minor)
{
    if (name == "sphere") return sphereSdf(size);
    if (name == "box") return boxSdf(size);
    if (name == "torus") return torusSdf(size, minor > 0.0 ? minor : size / 3.0);
    throw InputError("unknown shape '" + name + "' (sphere, box or torus)");
}

}  // namespace sculpt
