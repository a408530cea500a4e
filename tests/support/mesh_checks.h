// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file mesh_checks.h
/// @brief Test helpers: topology and measures of triangle meshes, computed by us and by VTK.

#include "core/mesh/triangle_mesh.h"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace sculpt::test {

/// Edge statistics of an indexed mesh (vertices identified by index).
struct MeshTopology {
    std::int64_t vertices = 0;  ///< vertices used by at least one triangle
    std::int64_t edges = 0;
    std::int64_t faces = 0;
    std::int64_t boundaryEdges = 0;     ///< edges with one triangle
    std::int64_t nonManifoldEdges = 0;  ///< edges with three or more triangles
    std::int64_t misorientedEdges = 0;  ///< interior edges traversed twice in one direction
    std::int64_t degenerateFaces = 0;   ///< triangles repeating a vertex index

    std::int64_t eulerCharacteristic() const { return vertices - edges + faces; }
    bool closedManifold() const
    {
        return boundaryEdges == 0 && nonManifoldEdges == 0 && misorientedEdges == 0 && degenerateFaces == 0;
    }
};

/// Counts edges and their incidences.
MeshTopology meshTopology(const TriangleMesh& mesh);

/// Signed enclosed volume (divergence theorem); positive for outward-facing triangles.
double meshVolume(const TriangleMesh& mesh);
/// Sum of triangle areas.
double meshArea(const TriangleMesh& mesh);
/// Triangles of each connected shell (triangles sharing a vertex), largest first.
std::vector<std::size_t> shellTriangleCounts(const TriangleMesh& mesh);

/// What VTK says of a mesh file: read with VTK's reader for its extension, points merged.
struct VtkMeshReport {
    std::int64_t triangles = 0;
    std::int64_t boundaryEdges = 0;     ///< vtkFeatureEdges
    std::int64_t nonManifoldEdges = 0;  ///< vtkFeatureEdges
    double volume = 0.0;                ///< vtkMassProperties
    double area = 0.0;                  ///< vtkMassProperties
};
VtkMeshReport vtkMeshReport(const std::filesystem::path& meshFile);

}  // namespace sculpt::test
