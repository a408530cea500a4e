// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file islands.h
/// @brief Islands: the disjoint solids of a model (a scan's specks, parts cut apart), found with
///        OpenVDB's segmentSDF (a cavity stays with the solid around it), kept or removed whole.

#include "core/field/field_image.h"

#include <openvdb/openvdb.h>

#include <vector>

namespace sculpt {

struct Island {
    openvdb::FloatGrid::Ptr grid;  ///< the island alone, on the field's voxels
    double volume = 0.0;           ///< world units cubed
    openvdb::BBoxd bounds;         ///< of its active voxels, world units
};

/// Every island of the field, largest first. Cost: the band.
std::vector<Island> findIslands(const FieldImage& field);

/// The field without the islands whose volume is under `minVolume` (world units cubed): the others
/// are united again (CSG union), so their voxels stay bit for bit unless two bands overlap.
/// Returns how many were removed.
std::size_t removeIslandsUnder(FieldImage& field, double minVolume);

/// The index (in findIslands' order) of the island holding or nearest `world` within
/// `reachWorld`, or -1 if none comes that near.
int islandAt(const std::vector<Island>& islands, const openvdb::Vec3d& world, double reachWorld);

/// Keeps only island `index` of `islands` (keep), or removes it (!keep), from `field`.
void keepOrRemoveIsland(FieldImage& field, const std::vector<Island>& islands, std::size_t index, bool keep);

}  // namespace sculpt
