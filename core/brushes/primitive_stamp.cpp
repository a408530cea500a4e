// SPDX-License-Identifier: Apache-2.0
/// @file primitive_stamp.cpp
/// @brief primitive: a primitive scene, its origin placed at the stamp, combined by its operation.

#include "core/brushes/brush_tools.h"
#include "core/field/csg_combine.h"
#include "core/local/local_patch.h"
#include "core/primitives/primitive_rasterizer.h"

namespace sculpt {

DirtyRegion stampPrimitives(FieldImage& field, const PrimitiveStamp& primitive, const BrushStamp& stamp,
                            LeafJournal* journal)
{
    const PrimitiveSet placed = primitive.primitives.translated(stamp.centreWorld);
    const openvdb::BBoxd box = placed.influence();
    const double reach = 0.5 * box.extents().length() + field.grid().background() + field.voxelSize();
    LocalPatch patch(field, Capsule::ball(box.getCenter(), reach));
    const FieldImage shape = rasterizePrimitives(placed, field.grid().transform(), field.halfWidthVoxels());
    combine(patch.field(), shape, primitive.operation);
    return patch.commit(field, journal);
}

}  // namespace sculpt
