// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file band_repair.h
/// @brief Float grids from other programs that are meant as distances but are not a narrow
///        band: a dense `phi` (Mantaflow: every voxel active, background 0, in cell units), a
///        band whose values exceed its background, a grid without the level-set class.

#include <openvdb/openvdb.h>

#include <string>

namespace sculpt {

/// Why `grid` is not a narrow band of signed distances (empty when it is one).
/// @throws InputError if it holds values that are not finite numbers.
std::string whyNotNarrowBand(const openvdb::FloatGrid& grid);

/// The signed distance to `grid`'s zero level (negative where it is negative), kept in a band
/// of `halfWidthVoxels` on each side, on the same transform and with the same name.
openvdb::FloatGrid::Ptr rebuildNarrowBand(const openvdb::FloatGrid& grid, double halfWidthVoxels);

}  // namespace sculpt
