// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file stl_file.h
/// @brief STL meshes, binary and text: three corners per triangle (joined where they coincide
///        by readMesh), the stored facet normals ignored.

#include "core/mesh/triangle_mesh.h"

#include <filesystem>

namespace sculpt {

/// Binary (an 80-byte header, a triangle count, 50 bytes per triangle) when the size matches its
/// count or the file does not open with "solid"; text otherwise.
/// @throws InputError naming the file: a binary file shorter than its count, a text file
///         whose "vertex" lines are not three per facet or hold bad numbers.
TriangleMesh readStl(const std::filesystem::path& path);

}  // namespace sculpt
