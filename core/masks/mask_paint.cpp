// SPDX-License-Identifier: Apache-2.0
#include "core/masks/mask_paint.h"

#include "core/local/capsule.h"
#include "core/local/local_patch.h"
#include "core/masks/mask_edit.h"

namespace sculpt {

DirtyRegion paintMask(FieldImage& field, const FalloffBall& ball, double amount, LeafJournal* journal)
{
    // Voxels as far as the band's edge from the ball hold closest points inside it.
    const Capsule reach = Capsule::ball(ball.centreWorld, ball.radiusWorld + field.grid().background());
    return rewriteMask(field, leavesMeeting(field.grid(), reach), journal,
                       [&](const openvdb::Coord& ijk, const MaskSite& site) {
                           return site.mask(ijk) + amount * ball.weightAt(site.footWorld(ijk));
                       });
}

}  // namespace sculpt
