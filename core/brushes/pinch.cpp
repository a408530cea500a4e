// SPDX-License-Identifier: Apache-2.0
/// @file pinch.cpp
/// @brief pinch: the surface moves towards the stroke line through the stamp (sharpens creases).

#include "core/brushes/brush_tools.h"
#include "core/local/local_patch.h"

#include <algorithm>
#include <cmath>

namespace sculpt {

namespace {

constexpr double kPinchFraction = 0.5;  // of the distance to the stroke line, per stamp

/// Largest q w(q) over q in [0, 1]: how far, in radii, a pull towards the centre can move a point.
double peakPull(Falloff falloff)
{
    double peak = 0.0;
    for (int i = 0; i <= 64; ++i) peak = std::max(peak, i / 64.0 * falloffWeight(falloff, i / 64.0));
    return peak;
}

}  // namespace

DirtyRegion pinch(FieldImage& field, const BrushSettings& brush, const BrushStamp& stamp, LeafJournal* journal)
{
    using openvdb::Vec3d;
    Vec3d axis = stamp.centreWorld - stamp.previousWorld;
    if (axis.length() < 1e-9 * brush.radiusWorld) axis = stamp.viewDirection;
    if (!(axis.length() > 0.0)) axis = Vec3d(0.0, 0.0, 1.0);
    axis.normalize();
    const FalloffBall ball{stamp.centreWorld, brush.radiusWorld, brush.falloff};
    const Capsule region = Capsule::ball(ball.centreWorld, ball.radiusWorld);
    const double total = kPinchFraction * brush.strength * stamp.pressure;
    const int n = substepsFor(total * peakPull(brush.falloff) * brush.radiusWorld, field.voxelSize());
    const double share = 1.0 - std::pow(1.0 - total, 1.0 / n);
    LocalPatch patch(field, region);
    for (int i = 0; i < n; ++i) {
        patch.advect(region, [&](const Vec3d& world) {
            const Vec3d onLine = ball.centreWorld + axis * (world - ball.centreWorld).dot(axis);
            return (onLine - world) * (share * ball.weightAt(world));
        });
        patch.redistance();
    }
    return patch.commit(field, journal);
}

}  // namespace sculpt
