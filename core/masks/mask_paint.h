// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file mask_paint.h
/// @brief The mask brush: one stamp paints or erases the mask on the surface under it.

#include "core/field/dirty_region.h"
#include "core/field/field_image.h"
#include "core/local/falloff.h"

namespace sculpt {

class LeafJournal;

/// Paints (amount > 0) or erases (amount < 0) the mask under `ball`: each voxel's mask gains (or
/// loses) |amount| x the falloff at its closest surface point, within [0, 1], so a few stamps
/// mask the middle of a stroke fully, as Blender's mask brush does. Saves each mask leaf in `journal`
/// before it first changes; returns (and marks dirty) the leaves changed. Cost: the ball's leaves.
DirtyRegion paintMask(FieldImage& field, const FalloffBall& ball, double amount, LeafJournal* journal);

}  // namespace sculpt
