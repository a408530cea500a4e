// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file off_file.h
/// @brief OFF meshes (Geomview, CGAL, Princeton's shape benchmark), which VTK cannot read.

#include "core/mesh/triangle_mesh.h"

#include <filesystem>

namespace sculpt {

/// The keyword [ST][C][N]OFF (texture coordinates, colours and normals after each position are
/// ignored), then "V F E" (on the keyword's line or the next), V vertex lines "x y z ...", F
/// face lines "n i0 ... i(n-1) [colour]" fanned into triangles; '#' starts a comment anywhere.
/// @throws InputError naming the file and line: 4OFF/nOFF, binary OFF, counts the file cannot
///         hold, bad numbers, faces of fewer than 3 vertices, indices out of range.
TriangleMesh readOff(const std::filesystem::path& path);

}  // namespace sculpt
