// SPDX-License-Identifier: Apache-2.0
#include "ui/view/block_polydata.h"

#include <glm/common.hpp>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTypeInt32Array.h>

#include <cstring>
#include <limits>

namespace sculpt::ui {

namespace {

vtkSmartPointer<vtkFloatArray> floatTriples(const std::vector<std::array<float, 3>>& values)
{
    auto array = vtkSmartPointer<vtkFloatArray>::New();
    array->SetNumberOfComponents(3);
    array->SetNumberOfTuples(vtkIdType(values.size()));
    if (!values.empty()) std::memcpy(array->GetPointer(0), values.data(), values.size() * sizeof(values[0]));
    return array;
}

/// The values of a VTK array of triples, copied out as triples.
template <typename Triple, typename Array>
std::vector<Triple> triplesOf(Array* array)
{
    static_assert(sizeof(Triple) == 3 * sizeof(*array->GetPointer(0)));
    std::vector<Triple> values(std::size_t(array->GetNumberOfValues() / 3));
    if (!values.empty()) std::memcpy(values.data(), array->GetPointer(0), values.size() * sizeof(Triple));
    return values;
}

}  // namespace

void append(BlockMesh& whole, const BlockMesh& part)
{
    const auto base = std::uint32_t(whole.positions.size());
    whole.positions.insert(whole.positions.end(), part.positions.begin(), part.positions.end());
    whole.normals.insert(whole.normals.end(), part.normals.begin(), part.normals.end());
    for (const auto& t : part.triangles) whole.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
}

std::pair<glm::dvec3, glm::dvec3> boundsOf(const std::array<float, 3>* points, std::size_t count)
{
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi = -lo;
    for (std::size_t i = 0; i < count; ++i) {
        const glm::dvec3 p(points[i][0], points[i][1], points[i][2]);
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    return {lo, hi};
}

vtkSmartPointer<vtkPolyData> polyDataOf(const BlockMesh& mesh)
{
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetData(floatTriples(mesh.positions));
    auto normals = floatTriples(mesh.normals);
    normals->SetName("Normals");
    // 32-bit cells: half the memory of vtkIdType's, and every chunk has far fewer than 2^31 indices.
    auto offsets = vtkSmartPointer<vtkTypeInt32Array>::New();
    auto connectivity = vtkSmartPointer<vtkTypeInt32Array>::New();
    const auto triangles = vtkIdType(mesh.triangles.size());
    offsets->SetNumberOfValues(triangles + 1);
    connectivity->SetNumberOfValues(3 * triangles);
    for (vtkIdType t = 0; t <= triangles; ++t) offsets->SetValue(t, std::int32_t(3 * t));
    if (triangles > 0) std::memcpy(connectivity->GetPointer(0), mesh.triangles.data(), std::size_t(3 * triangles) * 4);
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    cells->SetData(offsets, connectivity);
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(points);
    poly->GetPointData()->SetNormals(normals);
    poly->SetPolys(cells);
    return poly;
}

BlockMesh blockMeshOf(const vtkPolyData* poly)
{
    auto* data = const_cast<vtkPolyData*>(poly);  // VTK's getters are not const; nothing is changed
    BlockMesh mesh;
    mesh.positions = triplesOf<std::array<float, 3>>(vtkFloatArray::SafeDownCast(data->GetPoints()->GetData()));
    mesh.normals = triplesOf<std::array<float, 3>>(vtkFloatArray::SafeDownCast(data->GetPointData()->GetNormals()));
    mesh.triangles = triplesOf<std::array<std::uint32_t, 3>>(
        vtkTypeInt32Array::SafeDownCast(data->GetPolys()->GetConnectivityArray()));
    return mesh;
}

}  // namespace sculpt::ui
