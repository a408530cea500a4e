// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file placed_box.h
/// @brief Boxes of pieces: a field's surface box in its own world, and a box carried by a
///        placement (piece.h) into another world.

#include "core/field/field_image.h"

namespace sculpt {

/// The box of `field`'s leaves in its world: its surface and band (empty if it has none).
inline openvdb::BBoxd leafWorldBox(const FieldImage& field)
{
    openvdb::CoordBBox leaves;
    if (!field.grid().tree().evalLeafBoundingBox(leaves)) return {};
    return field.grid().transform().indexToWorld(leaves);
}

/// The box holding `box` carried by `m` (row vectors: p * m): its eight corners' box.
inline openvdb::BBoxd placedBox(const openvdb::BBoxd& box, const openvdb::Mat4d& m)
{
    openvdb::BBoxd placed;
    if (box.empty()) return placed;
    for (int c = 0; c < 8; ++c)
        placed.expand(
            m.transform(openvdb::Vec3d((c & 1 ? box.max() : box.min()).x(), (c & 2 ? box.max() : box.min()).y(),
                                       (c & 4 ? box.max() : box.min()).z())));
    return placed;
}

}  // namespace sculpt
