// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file voxel_size.h
/// @brief The voxel sizes a model may have, and the lattice of one.

#include <openvdb/math/Transform.h>

namespace sculpt {

/// Smallest voxel size a model may have: OpenVDB refuses transforms whose determinant (h^3)
/// is about 1e-15 or less ("Non-zero scale values required"), and lattices this fine hold no
/// shape a person sculpts or prints.
constexpr double kMinVoxelSize = 1e-4;

/// The lattice of voxel size h at the origin.
/// @throws InputError (not naming a file) if h is not a finite number of at least kMinVoxelSize.
openvdb::math::Transform::Ptr voxelTransform(double voxelSize);

}  // namespace sculpt
