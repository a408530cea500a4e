// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file sphere_stamp.h
/// @brief The elementary local edit: add (union) or carve (difference) a ball.
///
/// Writes phi = min(phi, d) (add) or phi = max(phi, -d) (carve), d the ball's signed distance,
/// only over the voxels within the ball's radius plus the band, activating voxels that enter
/// the band and deactivating (to +-background) those that leave it. The result is exact outside
/// the union and a conservative distance inside; brushes redistance afterwards.

#include "core/field/dirty_region.h"
#include "core/field/field_image.h"

namespace sculpt {

enum class CsgMode { Add, Carve };

/// Stamps a ball of `radiusWorld` at `centreWorld`; marks and returns the touched leaves.
/// Cost: the (2 (radius + band))^3 voxels around the ball, independent of the model's size.
/// @throws InputError if the radius is not positive and finite or the centre is not finite.
DirtyRegion stampSphere(FieldImage& field, const openvdb::Vec3d& centreWorld, double radiusWorld, CsgMode mode);

}  // namespace sculpt
