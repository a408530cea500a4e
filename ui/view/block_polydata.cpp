#include "ui/view/block_polydata.h"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <cstring>

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

}  // namespace

void append(BlockMesh& whole, const BlockMesh& part)
{
    const auto base = std::uint32_t(whole.positions.size());
    whole.positions.insert(whole.positions.end(), part.positions.begin(), part.positions.end());
    whole.normals.insert(whole.normals.end(), part.normals.begin(), part.normals.end());
    for (const auto& t : part.triangles) whole.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
}

vtkSmartPointer<vtkPolyData> polyDataOf(const BlockMesh& mesh)
{
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetData(floatTriples(mesh.positions));
    auto normals = floatTriples(mesh.normals);
    normals->SetName("Normals");
    auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
    auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
    offsets->SetNumberOfValues(vtkIdType(mesh.triangles.size() + 1));
    connectivity->SetNumberOfValues(vtkIdType(mesh.triangles.size() * 3));
    for (vtkIdType t = 0; t < vtkIdType(mesh.triangles.size()); ++t) {
        offsets->SetValue(t, 3 * t);
        for (int k = 0; k < 3; ++k) connectivity->SetValue(3 * t + k, mesh.triangles[size_t(t)][size_t(k)]);
    }
    offsets->SetValue(vtkIdType(mesh.triangles.size()), vtkIdType(3 * mesh.triangles.size()));
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    cells->SetData(offsets, connectivity);
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(points);
    poly->GetPointData()->SetNormals(normals);
    poly->SetPolys(cells);
    return poly;
}

}  // namespace sculpt::ui
