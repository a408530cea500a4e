// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file placement_check.h
/// @brief What a piece's placement may be, wherever one comes from (a document's metadata, a
///        stroke script, a gesture): an affine map of finite numbers that turns, scales by
///        1/1000 to 1000 without mirroring or flattening, and moves by at most 10^7 units; its
///        images then stay finite in single precision (meshes, exports).

#include <openvdb/Types.h>

#include <string>

namespace sculpt {

/// The largest distance a placement may move a piece, in world units.
inline constexpr double kMaxPlacementOffset = 1e7;
/// Scales a placement may apply: its volume's cube root within [1/k, k], its condition number
/// (Frobenius norms of it and its inverse) at most 3k.
inline constexpr double kMaxPlacementScale = 1e3;

/// Why `placement` may not place a piece ("it mirrors the piece"), or "" when it may.
std::string placementProblem(const openvdb::Mat4d& placement);

}  // namespace sculpt
