// SPDX-License-Identifier: Apache-2.0
/// @file add_carve.cpp
/// @brief add / carve: the union or difference of a ball swept as a capsule from the previous
///        stamp, blended into the surface by a smooth minimum whose width the falloff sets.

#include "core/brushes/brush_tools.h"
#include "core/local/local_patch.h"

#include <algorithm>
#include <cmath>

namespace sculpt {

namespace {

/// Polynomial smooth minimum: min(a, b) with a fillet of width k where they meet (k = 0: min).
double smoothMin(double a, double b, double k)
{
    if (k <= 0.0) return std::min(a, b);
    const double t = std::max(k - std::abs(a - b), 0.0) / k;
    return std::min(a, b) - t * t * k * 0.25;
}

/// Fillet width of add / carve, as a fraction of the ball's radius.
double filletFraction(Falloff falloff)
{
    switch (falloff) {
    case Falloff::Smooth: return 0.5;
    case Falloff::Sphere: return 0.25;
    case Falloff::Sharp: return 0.1;
    case Falloff::Constant: return 0.0;
    }
    return 0.0;
}

}  // namespace

DirtyRegion sweepBall(FieldImage& field, const BrushSettings& brush, const BrushStamp& stamp, CsgMode mode,
                      LeafJournal* journal)
{
    const double h = field.voxelSize(), background = field.grid().background();
    const double radius = brush.radiusWorld * brush.strength * stamp.pressure;
    // The fillet reads phi up to its width away from the surface: no wider than the band.
    const double fillet = std::min(filletFraction(brush.falloff) * radius, background - h);
    const Capsule ball{stamp.previousWorld, stamp.centreWorld, radius};
    LocalPatch patch(field, ball.grownBy(fillet + background + h));
    const float keptTile = float(mode == CsgMode::Add ? -background : background);
    patch.combineVoxels(patch.region(), keptTile, [&](const openvdb::Vec3d& world, float phi) {
        const double d = ball.axisDistance(world) - radius;
        return mode == CsgMode::Add ? smoothMin(phi, d, fillet) : -smoothMin(-phi, d, fillet);
    });
    patch.redistance();
    return patch.commit(field, journal);
}

}  // namespace sculpt
