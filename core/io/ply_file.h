// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file ply_file.h
/// @brief PLY meshes (Stanford): read in text and both binary byte orders, every length and index
///        checked against the file; written as binary little-endian with per-vertex normals.

#include "core/io/mesh_frame.h"
#include "core/mesh/triangle_mesh.h"

#include <filesystem>

namespace sculpt {

/// The vertex element's x, y, z (any numeric type) and the face element's `vertex_indices` (or
/// `vertex_index`) lists, fanned into triangles; other elements and properties are skipped.
/// @throws InputError naming the file: a header cut short or malformed, a body shorter than its
///         elements, a face naming no vertex, a list of absurd length.
TriangleMesh readPly(const std::filesystem::path& path);

/// Binary little-endian PLY: x y z (float) and, when the mesh has normals, nx ny nz; faces as
/// uchar-counted int lists; in `frame` (from LPS), its tag (SPACE=LPS) in a comment.
/// Written to `path` as given (writeMesh makes it atomic).
/// @throws InputError naming the file if it cannot be written.
void writePly(const TriangleMesh& mesh, const std::filesystem::path& path, MeshFrame frame = MeshFrame::Lps);

}  // namespace sculpt
