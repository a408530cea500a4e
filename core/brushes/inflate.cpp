// SPDX-License-Identifier: Apache-2.0
/// @file inflate.cpp
/// @brief inflate / deflate: the surface under the brush moves along its normal.

#include "core/brushes/brush_tools.h"
#include "core/local/local_patch.h"

namespace sculpt {

namespace {

constexpr double kInflateFraction = 0.1;  // of the radius, per stamp at full strength and pressure

}  // namespace

DirtyRegion inflate(FieldImage& field, const BrushSettings& brush, const BrushStamp& stamp, double direction,
                    LeafJournal* journal)
{
    const FalloffBall ball{stamp.centreWorld, brush.radiusWorld, brush.falloff};
    LocalPatch patch(field, Capsule::ball(ball.centreWorld, ball.radiusWorld));
    patch.offsetSurface(ball, direction * kInflateFraction * brush.radiusWorld * brush.strength * stamp.pressure);
    return patch.commit(field, journal);
}

}  // namespace sculpt
