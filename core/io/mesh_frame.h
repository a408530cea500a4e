// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file mesh_frame.h
/// @brief The frame a mesh file's coordinates are in, named in its header as Slicer writes and
///        reads it (SPACE=LPS in a PLY comment, an OBJ comment, an STL header): documents are
///        LPS (FieldImage::kFrame); RAS is for the tools that expect it (FreeSurfer, nibabel).

#include "core/mesh/triangle_mesh.h"

#include <filesystem>
#include <optional>
#include <string>

namespace sculpt {

enum class MeshFrame { Lps, Ras };

/// "SPACE=LPS" or "SPACE=RAS", as the header says it.
std::string meshFrameTag(MeshFrame frame);
/// `mesh` in the other frame: x and y negated (a half turn about z: the triangles keep their
/// winding), normals too.
TriangleMesh inOtherFrame(TriangleMesh mesh);
/// The frame the header of the mesh file at `path` declares (a SPACE= tag in its first 4 KiB),
/// if it declares one.
std::optional<MeshFrame> declaredMeshFrame(const std::filesystem::path& path);

}  // namespace sculpt
