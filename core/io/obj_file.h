#pragma once
/// @file obj_file.h
/// @brief Wavefront OBJ meshes: the positions and faces; texture coordinates, normals, groups
///        and materials are ignored.

#include "core/mesh/triangle_mesh.h"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace sculpt {

/// "v x y z [w | r g b]" and "f a b c ..." (each "i", "i/t", "i//n" or "i/t/n"; negative
/// indices count back from the latest vertex), faces fanned into triangles; '#' comments.
/// @throws InputError naming the file and line: a bad number, a face of fewer than 3 vertices,
///         an index naming no vertex (VTK's reader imports those as a wrong shape).
TriangleMesh readObj(const std::filesystem::path& path);

/// Writes meshes as the named objects ("o name") of one OBJ file, atomically, with normals where
/// a mesh has them: Blender and most tools import each object separately.
/// @throws InputError naming the file if its directory is missing or it cannot be written.
void writeObjObjects(const std::vector<std::pair<std::string, TriangleMesh>>& objects,
                     const std::filesystem::path& path);

}  // namespace sculpt
