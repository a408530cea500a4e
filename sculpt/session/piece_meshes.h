// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file piece_meshes.h
/// @brief A document's pieces as mesh files, each where it is placed: one file for one piece;
///        several as one OBJ of an object each, or (.ply, .stl) a file each named after the
///        target's stem and the piece ("head-label_3.ply"); a 3MF always holds them all, as an
///        object each with its colour, in the document's unit.

#include "core/io/mesh_frame.h"
#include "core/mesh/triangle_mesh.h"

#include <openvdb/Types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace sculpt {

/// A piece's surface in world coordinates, its name, and what a 3MF says of it.
struct PieceMesh {
    std::string name;
    TriangleMesh mesh;
    openvdb::Vec3f colour{0.8f, 0.8f, 0.8f};  ///< sRGB, 0..1
    std::string units = "mm";                 ///< the document's length unit
};

/// `mesh` (in its piece's own world) where `placement` puts it: positions moved, normals turned.
TriangleMesh placedMesh(TriangleMesh mesh, const openvdb::Mat4d& placement);

/// A piece's mesh as written: the file (shared by every piece of an OBJ) and its size.
struct WrittenMesh {
    std::filesystem::path file;
    std::string piece;  ///< empty for a document's only piece
    std::size_t vertices = 0, triangles = 0;
    bool sharedFile = false;  ///< one object of a file holding several (OBJ, 3MF)

    /// A line for the user ("wrote a.ply (piece 'eye'): 10 vertices, 16 triangles").
    std::string line() const;
};
/// A line per mesh written.
std::vector<std::string> linesOf(const std::vector<WrittenMesh>& written);

/// Writes the pieces' meshes as above, every target checked before any is written, in `frame`
/// (documents are LPS; RAS negates x and y), the frame named in each file's header.
/// @return what was written, a record per piece.
/// @throws InputError naming the file (an unknown extension, an unwritable target).
std::vector<WrittenMesh> writePieceMeshes(const std::vector<PieceMesh>& pieces, const std::filesystem::path& path,
                                          MeshFrame frame = MeshFrame::Lps);

}  // namespace sculpt
