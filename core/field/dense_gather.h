#pragma once
/// @file dense_gather.h
/// @brief Copies a box of a sparse tree into a dense array, leaf by leaf.
///
/// Stencil work (marching cubes, finite differences) runs fastest on a small dense copy: one
/// probe per overlapped leaf instead of one tree lookup per sample. Voxels of missing leaves take
/// the value of the tile (or background) that covers them.

#include <openvdb/openvdb.h>

namespace sculpt {

/// Fills `dst` with the values of `box` (inclusive), z varying fastest, then y, then x:
/// dst[((x - min.x) * dim.y + (y - min.y)) * dim.z + (z - min.z)]. `dst` holds box.volume().
void gatherDense(const openvdb::FloatTree& tree, const openvdb::CoordBBox& box, float* dst);

}  // namespace sculpt
