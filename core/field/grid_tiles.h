// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file grid_tiles.h
/// @brief The tiles of a float tree that are not its background (a value standing for a whole
///        8^3, 128^3 or 4096^3 block: a level set's inside, or damage), found by walking each
///        node's own table.
///
/// OpenVDB's tree-wide value iterators step through each upper node's 32,768 entries one by one
/// at tens of nanoseconds a step, so a small grid (a label's piece, one leaf) pays about a
/// millisecond a pass for tiles that are nearly all the background. A level set's inside is
/// tiles, so volumes, "is anything inside" and "is every value a number" must see those, cheaply.

#include <openvdb/openvdb.h>

#include <functional>

namespace sculpt {

/// One tile: the block it covers, its value and whether it is active.
using TileVisit = std::function<void(const openvdb::CoordBBox& block, float value, bool active)>;

/// Calls `visit` for every tile of `tree` (the root's and the internal nodes', never a voxel)
/// whose value is not the background's bits: every inside tile, every NaN.
void forEachTileOffBackground(const openvdb::FloatTree& tree, const TileVisit& visit);

}  // namespace sculpt
