// SPDX-License-Identifier: Apache-2.0
// Exported meshes, re-read by VTK: closed, 2-manifold, enclosing the grid's volume.

#include "core/base/errors.h"
#include "core/io/mesh_file.h"
#include "core/io/obj_file.h"
#include "core/mesh/field_measures.h"
#include "core/mesh/incremental_mesher.h"
#include "core/primitives/analytic_shapes.h"
#include "tests/support/mesh_checks.h"
#include "tests/support/reference_mesher.h"
#include "tests/support/temp_dir.h"

#include <gtest/gtest.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPLYReader.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <cmath>
#include <limits>

namespace sculpt {
namespace {

using test::TempDir;

class MeshFileFormats : public ::testing::TestWithParam<std::string> {};

TEST_P(MeshFileFormats, ExportIsClosedAndKeepsVolume)
{
    TempDir dir;
    const FieldImage torus = makeTorus(10.0, 4.0, 0.5);
    const TriangleMesh mesh = meshLevelSet(torus);
    const auto path = dir / ("torus" + GetParam());
    writeMesh(mesh, path);

    const test::VtkMeshReport vtk = test::vtkMeshReport(path);
    EXPECT_EQ(vtk.triangles, std::int64_t(mesh.triangles.size()));
    EXPECT_EQ(vtk.boundaryEdges, 0);
    EXPECT_EQ(vtk.nonManifoldEdges, 0);
    const double gridVolume = measureField(torus).volume;
    EXPECT_NEAR(vtk.volume, gridVolume, 0.01 * gridVolume);
    EXPECT_EQ(dir.entries().size(), 1u);  // no temporary left
}

INSTANTIATE_TEST_SUITE_P(AllFormats, MeshFileFormats, ::testing::Values(".ply", ".obj", ".stl"),
                         [](const auto& test) { return test.param.substr(1); });

TEST(MeshFile, ReferenceMeshIsOrientedOutwards)
{
    const TriangleMesh mesh = test::meshWithVolumeToMesh(makeSphere(10.0, 1.0));
    const test::MeshTopology topology = test::meshTopology(mesh);
    EXPECT_TRUE(topology.closedManifold());
    EXPECT_EQ(topology.eulerCharacteristic(), 2);
    EXPECT_GT(test::meshVolume(mesh), 0.0);
}

TEST(MeshFile, PlyExportCarriesUnitNormalsPointingOutwards)
{
    TempDir dir;
    const TriangleMesh mesh = meshLevelSet(makeSphere(10.0, 0.5));
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    writeMesh(mesh, dir / "ball.ply");
    // Read back by VTK: the normals are the file's, not recomputed.
    vtkNew<vtkPLYReader> reader;
    reader->SetFileName((dir / "ball.ply").c_str());
    reader->Update();
    vtkDataArray* normals = reader->GetOutput()->GetPointData()->GetNormals();
    ASSERT_NE(normals, nullptr);
    ASSERT_EQ(normals->GetNumberOfTuples(), vtkIdType(mesh.positions.size()));
    for (vtkIdType i = 0; i < normals->GetNumberOfTuples(); ++i) {
        double n[3], p[3];
        normals->GetTuple(i, n);
        reader->GetOutput()->GetPoint(i, p);
        const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        const double radial =
            (n[0] * p[0] + n[1] * p[1] + n[2] * p[2]) / (length * std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]));
        ASSERT_NEAR(length, 1.0, 1e-3) << i;
        ASSERT_GT(radial, 0.95) << i;  // outwards, within 18 degrees of the sphere's normal
    }
}

TEST(MeshFile, FormatFollowsExtension)
{
    EXPECT_EQ(meshFormatOf("a.PLY"), MeshFormat::Ply);
    EXPECT_EQ(meshFormatOf("dir/a.obj"), MeshFormat::Obj);
    EXPECT_EQ(meshFormatOf("a.stl"), MeshFormat::Stl);
    EXPECT_THROW(meshFormatOf("a.vtk"), InputError);
    EXPECT_THROW(meshFormatOf("noextension"), InputError);
}

TEST(MeshFile, MissingDirectoryIsAnInputError)
{
    TempDir dir;
    const TriangleMesh mesh = meshLevelSet(makeSphere(5.0, 1.0));
    EXPECT_THROW(writeMesh(mesh, dir / "missing" / "a.ply"), InputError);
    EXPECT_TRUE(dir.entries().empty());
}

// A vertex that is not a finite number is never written, in any format, and nothing is left.
TEST(MeshFile, AVertexThatIsNotANumberIsRefusedAndNothingWritten)
{
    TempDir dir;
    TriangleMesh mesh = meshLevelSet(makeSphere(5.0, 1.0));
    mesh.positions[7][1] = std::numeric_limits<float>::infinity();
    for (const char* name : {"a.ply", "a.obj", "a.stl"}) {
        try {
            writeMesh(mesh, dir / name);
            ADD_FAILURE() << name << " written";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("not a finite number"), std::string::npos) << e.what();
        }
    }
    EXPECT_THROW(writeObjObjects({{"ball", &mesh}}, dir / "b.obj"), InputError);
    EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
}  // namespace sculpt
