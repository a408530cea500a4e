// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file dense_gather.h
/// @brief Copies a box of a sparse tree into a dense array, leaf by leaf.
///
/// Stencil work (marching cubes, finite differences) runs fastest on a small dense copy: one
/// probe per overlapped leaf instead of one tree lookup per sample. Voxels of missing leaves take
/// the value of the tile (or background) that covers them.

#include <openvdb/openvdb.h>

#include <cstddef>

namespace sculpt {

/// Where (x, y, z) sits in a dense array of ny x nz columns: z varies fastest, then y, then x,
/// as in OpenVDB's leaves. The one order of every dense copy of the lattice (the scan importer's
/// arrays alone follow the scan's own order, x fastest, because they are filled from it).
constexpr std::size_t denseIndex(int ny, int nz, int x, int y, int z)
{
    return (std::size_t(x) * std::size_t(ny) + std::size_t(y)) * std::size_t(nz) + std::size_t(z);
}

/// Fills `dst` with the values of `box` (inclusive) in denseIndex order:
/// dst[denseIndex(dim.y, dim.z, x - min.x, y - min.y, z - min.z)]. `dst` holds box.volume().
void gatherDense(const openvdb::FloatTree& tree, const openvdb::CoordBBox& box, float* dst);

}  // namespace sculpt
