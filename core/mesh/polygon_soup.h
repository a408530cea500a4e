// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file polygon_soup.h
/// @brief Meshes as files hold them: polygons of any size, and vertices repeated where a format
///        stores corners per face (STL) or splits them at seams. The readers fan the polygons
///        and join the repeats so that edges are shared and topology can be counted.

#include "core/mesh/triangle_mesh.h"

#include <cstdint>
#include <vector>

namespace sculpt {

/// Appends the polygon `ids` (3 or more vertex indices) as a fan of triangles.
void fanPolygon(const std::vector<std::uint32_t>& ids, MeshArray<std::array<std::uint32_t, 3>>& triangles);

/// Joins vertices at exactly the same position (the first keeps its place; normals are dropped)
/// and drops triangles that then name a vertex twice.
void joinCoincidentVertices(TriangleMesh& mesh);

}  // namespace sculpt
