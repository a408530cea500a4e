// SPDX-License-Identifier: Apache-2.0
/// @file grab.cpp
/// @brief grab: the surface under the brush follows the pointer's drag from the previous stamp.

#include "core/brushes/brush_tools.h"
#include "core/local/local_patch.h"

namespace sculpt {

DirtyRegion grab(FieldImage& field, const BrushSettings& brush, const BrushStamp& stamp, LeafJournal* journal)
{
    using openvdb::Vec3d;
    const Vec3d drag = (stamp.centreWorld - stamp.previousWorld) * brush.strength;
    const int n = substepsFor(drag.length(), field.voxelSize());
    LocalPatch patch(field, Capsule{stamp.previousWorld, stamp.previousWorld + drag, brush.radiusWorld});
    if (drag.lengthSqr() == 0.0) return {};
    for (int i = 0; i < n; ++i) {
        // The grabbed region travels with the drag.
        const FalloffBall ball{stamp.previousWorld + drag * (double(i) / n), brush.radiusWorld, brush.falloff};
        patch.advect(Capsule::ball(ball.centreWorld, ball.radiusWorld),
                     [&](const Vec3d& world) { return drag * (ball.weightAt(world) / n); });
        patch.redistance();
    }
    return patch.commit(field, journal);
}

}  // namespace sculpt
