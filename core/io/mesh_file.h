#pragma once
/// @file mesh_file.h
/// @brief Mesh export for printing and rendering: binary PLY (ours, with normals), OBJ and binary
///        STL (VTK's writers).

#include "core/mesh/triangle_mesh.h"

#include <filesystem>

namespace sculpt {

enum class MeshFormat { Ply, Obj, Stl };

/// Format named by a path's extension (case-insensitive .ply, .obj, .stl).
/// @throws InputError naming the path if the extension is none of those.
MeshFormat meshFormatOf(const std::filesystem::path& path);

/// Writes `mesh` atomically (temporary file, then rename). PLY and OBJ carry normals when the
/// mesh has them.
/// @throws InputError naming the file if the extension is unknown, its directory is missing, or
///         the writer fails.
void writeMesh(const TriangleMesh& mesh, const std::filesystem::path& path);

}  // namespace sculpt
