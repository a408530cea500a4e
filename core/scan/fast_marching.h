// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file fast_marching.h
/// @brief First-order distances from a surface on a small dense box of voxels.
///
/// Sethian's fast marching: voxels are accepted in order of distance, each one's distance the
/// Godunov upwind solution of |grad d| = 1 over its accepted neighbours, starting from seeds (the
/// voxels next to the surface), which keep their distances.
/// The order is kept by buckets h/32 wide instead of a heap (an "untidy" queue, Yatziv, Bartesaghi
/// and Sapiro 2006): linear time, distances off by a small fraction of that width (a heap made
/// the march 3x slower). Marching stops at a limit, so the cost is the voxels nearer than it (a
/// narrow band), not the box. The scan importer runs it on boxes a little larger than its tiles.

#include <openvdb/math/Coord.h>

#include <cstdint>
#include <vector>

namespace sculpt {

class FastMarching {
public:
    /// @param dims      voxels of the box along x (fastest: the scan's order, which the importer fills
    ///                  it from; the rest of the engine uses denseIndex), y, z
    /// @param h         voxel edge
    /// @param limit     distance at which marching stops
    /// @param distance  unsigned distances: a seed's on entry, +inf elsewhere; on return every
    ///                  voxel nearer than `limit` holds its distance, the others >= limit or +inf.
    ///                  The box's faces only border the march: they keep their values.
    void run(const openvdb::math::Coord& dims, float h, float limit, std::vector<float>& distance);

private:
    std::vector<std::vector<std::uint32_t>> mBuckets;  // voxels by tentative distance; stale entries skipped
    std::vector<unsigned char> mState;
};

}  // namespace sculpt
