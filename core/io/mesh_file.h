// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file mesh_file.h
/// @brief Mesh export for printing and rendering: binary PLY (ours, with normals), OBJ and binary
///        STL (VTK's writers), 3MF (ours, threemf_file.h).

#include "core/io/mesh_frame.h"
#include "core/mesh/triangle_mesh.h"

#include <filesystem>

namespace sculpt {

enum class MeshFormat { Ply, Obj, Stl, ThreeMf };

/// Format named by a path's extension (case-insensitive .ply, .obj, .stl, .3mf).
/// @throws InputError naming the path if the extension is none of those.
MeshFormat meshFormatOf(const std::filesystem::path& path);

/// Writes `mesh` (LPS, as documents) atomically (temporary file, then rename), in `frame`: its
/// header names it (SPACE=LPS: a PLY comment, an OBJ comment, the STL header), RAS negates x
/// and y. PLY and OBJ carry normals when the mesh has them; a 3MF holds it as one grey object in
/// millimetres (writeThreeMf says other units and colours).
/// @throws InputError naming the file if the extension is unknown, its directory is missing, or
///         the writer fails.
void writeMesh(const TriangleMesh& mesh, const std::filesystem::path& path, MeshFrame frame = MeshFrame::Lps);

}  // namespace sculpt
