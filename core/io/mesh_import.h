// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file mesh_import.h
/// @brief Triangle meshes (OBJ, PLY, STL, OFF) into editable field images.
///
/// Each format has a reader of our own that checks every count, length and index against the
/// file before allocating or indexing (VTK's readers crash on cut PLY files and import OBJ
/// faces naming no vertex as wrong shapes); polygons are fanned into triangles and coincident
/// vertices joined. The mesh's edges are
/// counted first: a closed 2-manifold (every edge shared by exactly two triangles) converts
/// exactly; an open or non-manifold mesh still converts, with openvdb's sign classification
/// deciding inside and outside as well as it can, and the report says how many edges are
/// open so the caller can warn. Conversion: openvdb::tools::meshToLevelSet (exact distances to
/// the triangles in the band).

#include "core/base/progress.h"
#include "core/field/field_image.h"
#include "core/mesh/triangle_mesh.h"

#include <filesystem>

namespace sculpt {

/// True for .obj, .ply, .stl and .off paths.
bool isMeshPath(const std::filesystem::path& path);

/// Reads a mesh file into shared-vertex triangles, in LPS: a header declaring SPACE=RAS (as
/// Slicer writes it) has x and y negated; one declaring nothing is taken as LPS.
/// @throws InputError naming the file: unknown extension, unreadable, corrupt, no triangles,
///         non-finite coordinates.
TriangleMesh readMesh(const std::filesystem::path& path);

struct MeshImportReport {
    std::size_t triangles = 0;
    std::size_t boundaryEdges = 0;      ///< edges of one triangle: holes
    std::size_t nonManifoldEdges = 0;   ///< edges of three or more triangles
    long long eulerCharacteristic = 0;  ///< V - E + F, a vertex counted once per fan of triangles
    bool closed() const { return boundaryEdges == 0 && nonManifoldEdges == 0; }
};

/// Counts the mesh's triangles and its open and non-manifold edges.
MeshImportReport inspectMesh(const TriangleMesh& mesh);

/// The mesh as a level set of the given voxel size.
/// @throws InputError if the voxel size is not positive or the result would not fit in memory.
/// Cancelled if `progress` says stop.
FieldImage meshToField(const TriangleMesh& mesh, double voxelSizeWorld, const Progress& progress = {});

/// A voxel size giving about `voxelsAcross` voxels along the mesh's longest side.
double voxelSizeFor(const TriangleMesh& mesh, double voxelsAcross = 256.0);

}  // namespace sculpt
