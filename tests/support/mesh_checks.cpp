// SPDX-License-Identifier: Apache-2.0
#include "tests/support/mesh_checks.h"

#include "core/base/union_find.h"

#include <vtkCleanPolyData.h>
#include <vtkFeatureEdges.h>
#include <vtkMassProperties.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkPLYReader.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkTriangleFilter.h>

#include <algorithm>
#include <map>
#include <stdexcept>
#include <utility>

namespace sculpt::test {

using Vec = std::array<double, 3>;

namespace {

Vec at(const TriangleMesh& mesh, std::uint32_t i)
{
    const auto& p = mesh.positions[i];
    return {p[0], p[1], p[2]};
}

Vec cross(const Vec& a, const Vec& b)
{
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

template <typename Reader>
vtkSmartPointer<vtkPolyDataAlgorithm> newReader(const std::filesystem::path& file)
{
    auto reader = vtkSmartPointer<Reader>::New();
    reader->SetFileName(file.c_str());
    return reader;
}

vtkSmartPointer<vtkPolyData> readWithVtk(const std::filesystem::path& file)
{
    const std::string ext = file.extension().string();
    vtkSmartPointer<vtkPolyDataAlgorithm> reader;
    if (ext == ".ply") reader = newReader<vtkPLYReader>(file);
    else if (ext == ".obj") reader = newReader<vtkOBJReader>(file);
    else if (ext == ".stl") reader = newReader<vtkSTLReader>(file);
    else throw std::invalid_argument("no VTK reader for " + file.string());
    // STL and OBJ repeat a vertex per face or per normal: merge coincident points.
    vtkNew<vtkCleanPolyData> clean;
    clean->SetInputConnection(reader->GetOutputPort());
    clean->SetTolerance(0.0);
    clean->PointMergingOn();
    vtkNew<vtkTriangleFilter> triangles;
    triangles->SetInputConnection(clean->GetOutputPort());
    triangles->Update();
    return triangles->GetOutput();
}

std::int64_t featureEdgeCount(vtkPolyData* poly, bool boundary)
{
    vtkNew<vtkFeatureEdges> edges;
    edges->SetInputData(poly);
    edges->FeatureEdgesOff();
    edges->ManifoldEdgesOff();
    edges->SetBoundaryEdges(boundary);
    edges->SetNonManifoldEdges(!boundary);
    edges->Update();
    return edges->GetOutput()->GetNumberOfCells();
}

}  // namespace

MeshTopology meshTopology(const TriangleMesh& mesh)
{
    // (min, max) -> (count of min->max traversals, count of max->min traversals)
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<int, int>> edges;
    std::vector<bool> used(mesh.positions.size(), false);
    MeshTopology t;
    t.faces = std::int64_t(mesh.triangles.size());
    for (const auto& tri : mesh.triangles) {
        if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) ++t.degenerateFaces;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = tri[k], b = tri[(k + 1) % 3];
            used[a] = true;
            auto& e = edges[{std::min(a, b), std::max(a, b)}];
            (a < b ? e.first : e.second) += 1;
        }
    }
    for (bool u : used) t.vertices += u ? 1 : 0;
    t.edges = std::int64_t(edges.size());
    for (const auto& [key, uses] : edges) {
        const int total = uses.first + uses.second;
        if (total == 1) ++t.boundaryEdges;
        else if (total > 2) ++t.nonManifoldEdges;
        else if (uses.first != 1) ++t.misorientedEdges;
    }
    return t;
}

double meshVolume(const TriangleMesh& mesh)
{
    double sixVolume = 0.0;
    for (const auto& tri : mesh.triangles) {
        const Vec a = at(mesh, tri[0]), b = at(mesh, tri[1]), c = at(mesh, tri[2]);
        const Vec n = cross(b, c);
        sixVolume += a[0] * n[0] + a[1] * n[1] + a[2] * n[2];
    }
    return sixVolume / 6.0;
}

double meshArea(const TriangleMesh& mesh)
{
    double twiceArea = 0.0;
    for (const auto& tri : mesh.triangles) {
        const Vec a = at(mesh, tri[0]);
        const Vec n = cross(sub(at(mesh, tri[1]), a), sub(at(mesh, tri[2]), a));
        twiceArea += std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    }
    return twiceArea / 2.0;
}

std::vector<std::size_t> shellTriangleCounts(const TriangleMesh& mesh)
{
    UnionFind sets(mesh.positions.size());
    for (const auto& t : mesh.triangles) {
        sets.join(t[1], t[0]);
        sets.join(t[2], t[0]);
    }
    std::map<std::uint32_t, std::size_t> counts;
    for (const auto& t : mesh.triangles) ++counts[sets.find(t[0])];
    std::vector<std::size_t> sizes;
    for (const auto& [root, count] : counts) sizes.push_back(count);
    std::sort(sizes.rbegin(), sizes.rend());
    return sizes;
}

VtkMeshReport vtkMeshReport(const std::filesystem::path& meshFile)
{
    const auto poly = readWithVtk(meshFile);
    VtkMeshReport r;
    r.triangles = poly->GetNumberOfPolys();
    r.boundaryEdges = featureEdgeCount(poly, true);
    r.nonManifoldEdges = featureEdgeCount(poly, false);
    vtkNew<vtkMassProperties> mass;
    mass->SetInputData(poly);
    mass->Update();
    r.volume = mass->GetVolume();
    r.area = mass->GetSurfaceArea();
    return r;
}

}  // namespace sculpt::test
