#pragma once
/// @file mask_regions.h
/// @brief Face-connected regions of a bit mask (a BoolTree's active voxels and tiles).
///
/// A two-level flood fill: inside each 8^3 leaf the region grows by bit operations on its
/// 512-bit mask, and crosses to the neighbouring leaves through the bits on the leaf's faces.
/// Memory: the region and a queue of leaf faces. OpenVDB's extractActiveVoxelSegmentMasks
/// reserves, for every region, room for the segments of all leaves: 223 MiB for a brain scan's
/// 674 islands and bubbles.

#include <openvdb/openvdb.h>

#include <functional>

namespace sculpt {

/// The face-connected region of `mask`'s active voxels that holds `seed`: empty if the seed is
/// not active. Active tiles count as their voxels; the region holds leaves only.
openvdb::BoolTree::Ptr connectedRegion(const openvdb::BoolTree& mask, const openvdb::Coord& seed);

/// Calls `visit` with every face-connected region of `mask`, in the order of their first voxels.
void forEachConnectedRegion(const openvdb::BoolTree& mask, const std::function<void(openvdb::BoolTree::Ptr region)>& visit);

} // namespace sculpt
