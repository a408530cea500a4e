// SPDX-License-Identifier: Apache-2.0
#include "core/io/mesh_file.h"

#include "core/base/atomic_file.h"
#include "core/base/errors.h"
#include "core/base/file_extension.h"
#include "core/io/obj_file.h"
#include "core/io/ply_file.h"
#include "core/io/threemf_file.h"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSTLWriter.h>

#include <algorithm>
#include <cctype>

namespace sculpt {

namespace fs = std::filesystem;

namespace {

vtkSmartPointer<vtkPolyData> toPolyData(const TriangleMesh& mesh)
{
    vtkNew<vtkPoints> points;
    points->SetDataTypeToFloat();
    points->SetNumberOfPoints(vtkIdType(mesh.positions.size()));
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        points->SetPoint(vtkIdType(i), mesh.positions[i].data());
    }
    vtkNew<vtkCellArray> polys;
    polys->AllocateExact(vtkIdType(mesh.triangles.size()), vtkIdType(3 * mesh.triangles.size()));
    for (const auto& t : mesh.triangles) {
        const vtkIdType ids[3] = {t[0], t[1], t[2]};
        polys->InsertNextCell(3, ids);
    }
    auto polyData = vtkSmartPointer<vtkPolyData>::New();
    polyData->SetPoints(points);
    polyData->SetPolys(polys);
    if (!mesh.normals.empty()) {
        vtkNew<vtkFloatArray> normals;
        normals->SetName("Normals");
        normals->SetNumberOfComponents(3);
        normals->SetNumberOfTuples(vtkIdType(mesh.normals.size()));
        for (size_t i = 0; i < mesh.normals.size(); ++i) {
            normals->SetTypedTuple(vtkIdType(i), mesh.normals[i].data());
        }
        polyData->GetPointData()->SetNormals(normals);
    }
    return polyData;
}

template <typename Writer>
bool writeWith(Writer* writer, vtkPolyData* polyData, const fs::path& path)
{
    writer->SetFileName(path.c_str());
    writer->SetInputData(polyData);
    return writer->Write() == 1;
}

/// `mesh` (LPS) as `format` in `frame`, its header naming the frame.
bool writeFormat(MeshFormat format, const TriangleMesh& mesh, const fs::path& path, MeshFrame frame)
{
    switch (format) {
    case MeshFormat::Ply:
        writePly(mesh, path, frame);  // ours: VTK's PLY writer drops the normals
        return true;
    case MeshFormat::Obj: writeObjFile({{"", &mesh}}, path, frame); return true;
    case MeshFormat::Stl: {
        vtkNew<vtkSTLWriter> writer;
        writer->SetFileTypeToBinary();
        writer->SetHeader(("written by sculpt " + meshFrameTag(frame)).c_str());  // Slicer reads the tag
        if (frame == MeshFrame::Ras) return writeWith(writer.Get(), toPolyData(inOtherFrame(mesh)), path);
        return writeWith(writer.Get(), toPolyData(mesh), path);
    }
    case MeshFormat::ThreeMf: writeThreeMf({{"", &mesh, openvdb::Vec3f(0.8f)}}, path, "mm", frame); return true;
    }
    return false;
}

}  // namespace

MeshFormat meshFormatOf(const fs::path& path)
{
    const std::string ext = lowerExtension(path);
    if (ext == ".ply") return MeshFormat::Ply;
    if (ext == ".obj") return MeshFormat::Obj;
    if (ext == ".stl") return MeshFormat::Stl;
    if (ext == ".3mf") return MeshFormat::ThreeMf;
    throw InputError(path.string() + ": unknown mesh extension '" + path.extension().string() +
                     "' (expected .ply, .obj, .stl or .3mf)");
}

void writeMesh(const TriangleMesh& mesh, const fs::path& path, MeshFrame frame)
{
    const MeshFormat format = meshFormatOf(path);
    if (!mesh.finite()) throw InputError(path.string() + ": a vertex is not a finite number: not written");
    AtomicFile out(path);
    std::error_code ec;
    // The temporary exists from the start (AtomicFile): a writer that wrote nothing left it empty.
    if (!writeFormat(format, mesh, out.temporaryPath(), frame) || fs::file_size(out.temporaryPath(), ec) == 0 || ec) {
        throw InputError(path.string() + ": the mesh writer failed (disk full or no permission?)");
    }
    out.commit();
}

}  // namespace sculpt
