// SPDX-License-Identifier: Apache-2.0
/// @file smooth.cpp
/// @brief smooth: mean-curvature flow under the brush, weighted by its falloff; with keepVolume
///        the volume it removed under the brush is given back by an offset of the same falloff.

#include "core/brushes/brush_tools.h"
#include "core/local/local_patch.h"
#include "core/motion/level_set_evolution.h"

#include <cmath>
#include <limits>
#include <utility>

namespace sculpt {

namespace {

constexpr double kSmoothChunk = 0.5;  // beta t / h^2 between redistancings

/// Volume inside the surface within `region` and the area weighted by the ball's falloff, from
/// smeared Heaviside and delta functions of phi (1.5 voxels wide). One thread, voxel order:
/// deterministic.
std::pair<double, double> volumeAndWeightedArea(const openvdb::FloatGrid& grid, const Capsule& region,
                                                const FalloffBall& ball)
{
    const auto& xform = grid.transform();
    const double h = xform.voxelSize()[0], epsilon = 1.5 * h, cell = h * h * h;
    const openvdb::Vec3d reach(region.radius);
    const openvdb::CoordBBox box(xform.worldToIndexCellCentered(region.from - reach),
                                 xform.worldToIndexCellCentered(region.from + reach));
    const auto acc = grid.getConstAccessor();
    double volume = 0.0, area = 0.0;
    for (auto ijk = box.begin(); ijk; ++ijk) {
        const openvdb::Vec3d world = xform.indexToWorld(*ijk);
        if (!region.contains(world)) continue;
        const double phi = acc.getValue(*ijk);
        if (phi <= -epsilon) {
            volume += cell;
        } else if (phi < epsilon) {
            const double t = -phi / epsilon;
            volume += cell * 0.5 * (1.0 + t + std::sin(M_PI * t) / M_PI);
            area += cell * ball.weightAt(world) * (1.0 + std::cos(M_PI * t)) / (2.0 * epsilon);
        }
    }
    return {volume, area};
}

/// Gives back, by offsetting the surface under `ball`, the volume the patch lost inside `region`.
void refillVolumeUnder(LocalPatch& patch, const FalloffBall& ball, const Capsule& region, double targetVolume)
{
    for (int pass = 0; pass < 2; ++pass) {  // the second pass corrects the first's discretisation
        const auto [volume, weightedArea] = volumeAndWeightedArea(patch.field().grid(), region, ball);
        if (!(weightedArea > 0.0)) return;
        patch.offsetSurface(ball, (targetVolume - volume) / weightedArea);
    }
}

}  // namespace

DirtyRegion smoothUnder(FieldImage& field, const BrushSettings& brush, const BrushStamp& stamp, LeafJournal* journal)
{
    const double h = field.voxelSize();
    const FalloffBall ball{stamp.centreWorld, brush.radiusWorld, brush.falloff};
    LocalPatch patch(field, Capsule::ball(ball.centreWorld, ball.radiusWorld));
    const Capsule measured = Capsule::ball(ball.centreWorld, ball.radiusWorld + field.grid().background());
    const double volumeBefore =
        brush.keepVolume ? volumeAndWeightedArea(patch.field().grid(), measured, ball).first : 0.0;
    MotionTerms terms;
    terms.smooth = SmoothTerm{h * h, ball};
    // Curvature flow carries the band edge's error inwards by sqrt(2 beta t): redistance the
    // patch (cheaply, locally) every beta t = h^2 / 2 instead of the evolution's whole-grid tracker.
    EvolutionOptions options;
    options.redistanceAfterMovingVoxels = options.redistanceAfterDiffusingVoxels2 =
        std::numeric_limits<double>::infinity();
    options.firstOrderTime = true;
    const double duration = brush.strength * stamp.pressure;
    const int chunks = std::max(1, int(std::ceil(duration / kSmoothChunk - 1e-9)));
    for (int i = 0; i < chunks; ++i) {
        LevelSetEvolution(patch.field(), terms, options).advance(duration / chunks);
        patch.redistance();
    }
    if (brush.keepVolume) refillVolumeUnder(patch, ball, measured, volumeBefore);
    return patch.commit(field, journal);
}

}  // namespace sculpt
