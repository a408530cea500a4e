// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file surface_ray.h
/// @brief The first crossing of a ray with the zero level set of a field (as it is, or as it was
///        before a journal's edits), by sphere tracing on the trilinear field.
///
/// Phi is a distance (clamped to the band outside it), so a step of half of |phi| cannot pass
/// the surface; steps never fall under a tenth of a voxel, and a sign change between two samples
/// is refined by bisection. Only the ray's part inside `box` is searched: a ray from a far
/// camera costs the voxels it crosses there, about one look-up per voxel, not the model.

#include "core/field/pre_edit_field.h"

#include <optional>

namespace sculpt {

struct RayCrossing {
    openvdb::Vec3d position{0.0};          ///< world
    openvdb::Vec3d normal{0.0, 0.0, 1.0};  ///< unit, outwards (along grad phi)
};

/// The ray's first crossing of phi = 0 at t >= 0 inside `box` (index space, e.g. the field's leaf
/// box); from inside the model, that is where it leaves. `direction` need not be unit.
std::optional<RayCrossing> firstSurfaceCrossing(const PreEditField& field, const openvdb::CoordBBox& box,
                                                const openvdb::Vec3d& originWorld,
                                                const openvdb::Vec3d& directionWorld);

}  // namespace sculpt
