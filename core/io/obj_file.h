// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file obj_file.h
/// @brief Wavefront OBJ meshes: the positions and faces; texture coordinates, normals, groups
///        and materials are ignored.

#include "core/io/mesh_frame.h"
#include "core/mesh/triangle_mesh.h"

#include <filesystem>
#include <string>
#include <vector>

namespace sculpt {

/// "v x y z [w | r g b]" and "f a b c ..." (each "i", "i/t", "i//n" or "i/t/n"; negative
/// indices count back from the latest vertex), faces fanned into triangles; '#' comments.
/// @throws InputError naming the file and line: a bad number, a face of fewer than 3 vertices,
///         an index naming no vertex (VTK's reader imports those as a wrong shape).
TriangleMesh readObj(const std::filesystem::path& path);

/// A mesh to write as an OBJ object ("o name"; none for an empty name).
struct ObjObject {
    std::string name;
    const TriangleMesh* mesh;
};

/// Writes `objects` into one OBJ file at `path` (not atomically), with normals where a mesh has
/// them, in `frame` (from LPS; its tag in a comment): Blender and most tools import each object
/// separately.
/// @throws InputError naming the file if its directory is missing or it cannot be written.
void writeObjFile(const std::vector<ObjObject>& objects, const std::filesystem::path& path,
                  MeshFrame frame = MeshFrame::Lps);
/// writeObjFile, atomically (a temporary file, then a rename).
void writeObjObjects(const std::vector<ObjObject>& objects, const std::filesystem::path& path,
                     MeshFrame frame = MeshFrame::Lps);

}  // namespace sculpt
