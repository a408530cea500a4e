// SPDX-License-Identifier: Apache-2.0
/// @file follow.cpp
/// @brief follow: the surface under the brush moves part of its way to a target surface (the
///        level-set motion's target term, restricted to the brush and weighted by its falloff).

#include "core/brushes/brush_tools.h"
#include "core/local/local_patch.h"

#include <openvdb/tools/Interpolation.h>

namespace sculpt {

DirtyRegion follow(FieldImage& field, const BrushSettings& brush, const BrushStamp& stamp, LeafJournal* journal)
{
    const FalloffBall ball{stamp.centreWorld, brush.radiusWorld, brush.falloff};
    LocalPatch patch(field, Capsule::ball(ball.centreWorld, ball.radiusWorld));
    const openvdb::FloatGrid& target = brush.target->grid();
    // The tree's own reads (no accessor cache) are safe from the patch's threads.
    const openvdb::tools::GridSampler<openvdb::FloatTree, openvdb::tools::BoxSampler> sampler(target.tree(),
                                                                                              target.transform());
    // Beyond its band the target reads +-background: far parts approach a band width per stamp.
    patch.approach(ball, brush.strength * stamp.pressure, target.background(),
                   [&](const openvdb::Vec3d& foot) { return sampler.wsSample(foot); });
    return patch.commit(field, journal);
}

}  // namespace sculpt
