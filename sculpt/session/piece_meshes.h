#pragma once
/// @file piece_meshes.h
/// @brief A document's pieces as mesh files, each where it is placed: one file for one piece;
///        several as one OBJ of an object each, or (.ply, .stl) a file each named after the
///        target's stem and the piece ("head-label_3.ply").

#include "core/io/mesh_frame.h"
#include "core/mesh/triangle_mesh.h"

#include <openvdb/Types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace sculpt {

/// A piece's surface in world coordinates, and its name.
struct PieceMesh {
    std::string name;
    TriangleMesh mesh;
};

/// `mesh` (in its piece's own world) where `placement` puts it: positions moved, normals turned.
TriangleMesh placedMesh(TriangleMesh mesh, const openvdb::Mat4d& placement);

/// Writes the pieces' meshes as above, every target checked before any is written, in `frame`
/// (documents are LPS; RAS negates x and y), the frame named in each file's header.
/// @return a line per piece for the user ("wrote a.ply (piece 'eye'): 10 vertices, 16 triangles").
/// @throws InputError naming the file (an unknown extension, an unwritable target).
std::vector<std::string> writePieceMeshes(const std::vector<PieceMesh>& pieces, const std::filesystem::path& path,
                                          MeshFrame frame = MeshFrame::Lps);

}  // namespace sculpt
