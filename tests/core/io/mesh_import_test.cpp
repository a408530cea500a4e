// SPDX-License-Identifier: Apache-2.0
// Importing meshes (core/mesh_import.h): closed meshes keep their volume, open ones are reported,
// bad files are refused.

#include "core/base/errors.h"
#include "core/io/mesh_file.h"
#include "core/io/mesh_import.h"
#include "core/mesh/incremental_mesher.h"
#include "core/primitives/analytic_shapes.h"
#include "tests/support/file_bytes.h"
#include "tests/support/mesh_checks.h"
#include "tests/support/progress_log.h"
#include "tests/support/temp_dir.h"

#include <gtest/gtest.h>
#include <vtkNew.h>
#include <vtkOBJWriter.h>
#include <vtkPLYWriter.h>
#include <vtkSTLWriter.h>
#include <vtkSphereSource.h>
#include <vtkTriangleFilter.h>

#include <fstream>
#include <map>
#include <sstream>

namespace sculpt {
namespace {

TEST(MeshImport, ClosedMeshesInEveryFormatKeepTheirVolume)
{
    test::TempDir dir;
    vtkNew<vtkSphereSource> sphere;
    sphere->SetRadius(10.0);
    sphere->SetCenter(3.0, -2.0, 5.0);
    sphere->SetThetaResolution(64);
    sphere->SetPhiResolution(64);
    vtkNew<vtkTriangleFilter> triangles;
    triangles->SetInputConnection(sphere->GetOutputPort());
    vtkNew<vtkSTLWriter> stl;
    stl->SetInputConnection(triangles->GetOutputPort());
    stl->SetFileName((dir / "ball.stl").c_str());
    stl->Write();
    vtkNew<vtkPLYWriter> ply;
    ply->SetInputConnection(triangles->GetOutputPort());
    ply->SetFileName((dir / "ball.ply").c_str());
    ply->Write();
    vtkNew<vtkOBJWriter> obj;
    obj->SetInputConnection(triangles->GetOutputPort());
    obj->SetFileName((dir / "ball.obj").c_str());
    obj->Write();
    {  // OFF by hand: a cube of side 8 with quad faces
        std::ofstream off(dir / "cube.off");
        off << "OFF\n8 6 0\n";
        for (int i = 0; i < 8; ++i)
            off << (i & 1 ? 4 : -4) << " " << (i & 2 ? 4 : -4) << " " << (i & 4 ? 4 : -4) << "\n";
        off << "4 0 2 3 1\n4 4 5 7 6\n4 0 1 5 4\n4 2 6 7 3\n4 0 4 6 2\n4 1 3 7 5\n";
    }
    for (const char* name : {"ball.stl", "ball.ply", "ball.obj", "cube.off"}) {
        const TriangleMesh mesh = readMesh(dir / name);
        const MeshImportReport report = inspectMesh(mesh);
        EXPECT_TRUE(report.closed()) << name << ": " << report.boundaryEdges << " open edges";
        const double own = std::abs(test::meshVolume(mesh));
        const FieldImage field = meshToField(mesh, 0.25);
        EXPECT_NEAR(test::meshVolume(meshLevelSet(field)), own, 0.01 * own) << name;
    }
}

/// A VTK sphere written by VTK's writers in every variant they have, plus a big-endian PLY.
std::vector<std::string> writeSphereInEveryVariant(const test::TempDir& dir)
{
    vtkNew<vtkSphereSource> sphere;
    sphere->SetRadius(7.0);
    sphere->SetThetaResolution(24);
    sphere->SetPhiResolution(24);
    vtkNew<vtkTriangleFilter> triangles;
    triangles->SetInputConnection(sphere->GetOutputPort());
    vtkNew<vtkPLYWriter> ply;
    ply->SetInputConnection(triangles->GetOutputPort());
    ply->SetFileName((dir / "little.ply").c_str());
    ply->SetFileTypeToBinary();
    ply->SetDataByteOrderToLittleEndian();
    ply->Write();
    ply->SetFileName((dir / "big.ply").c_str());
    ply->SetDataByteOrderToBigEndian();
    ply->Write();
    ply->SetFileName((dir / "text.ply").c_str());
    ply->SetFileTypeToASCII();
    ply->Write();
    vtkNew<vtkSTLWriter> stl;
    stl->SetInputConnection(triangles->GetOutputPort());
    stl->SetFileName((dir / "binary.stl").c_str());
    stl->SetFileTypeToBinary();
    stl->Write();
    stl->SetFileName((dir / "text.stl").c_str());
    stl->SetFileTypeToASCII();
    stl->Write();
    vtkNew<vtkOBJWriter> obj;
    obj->SetInputConnection(triangles->GetOutputPort());
    obj->SetFileName((dir / "ball.obj").c_str());
    obj->Write();
    return {"little.ply", "big.ply", "text.ply", "binary.stl", "text.stl", "ball.obj"};
}

TEST(MeshImport, OurReadersAgreeWithVtksOnFilesVtkWrote)
{
    test::TempDir dir;
    for (const std::string& name : writeSphereInEveryVariant(dir)) {
        const TriangleMesh mesh = readMesh(dir / name);
        const test::VtkMeshReport vtk = test::vtkMeshReport(dir / name);
        EXPECT_EQ(std::int64_t(mesh.triangles.size()), vtk.triangles) << name;
        EXPECT_NEAR(test::meshVolume(mesh), vtk.volume, 1e-4 * vtk.volume) << name;
        EXPECT_TRUE(test::meshTopology(mesh).closedManifold()) << name;  // corners joined (STL)
        EXPECT_EQ(test::meshTopology(mesh).eulerCharacteristic(), 2) << name;
    }
}

TEST(MeshImport, OpenMeshesAreReportedAndStillImported)
{
    vtkNew<vtkSphereSource> sphere;
    sphere->SetRadius(5.0);
    sphere->Update();
    test::TempDir dir;
    vtkNew<vtkSTLWriter> stl;
    stl->SetInputConnection(sphere->GetOutputPort());
    stl->SetFileName((dir / "ball.stl").c_str());
    stl->Write();
    TriangleMesh mesh = readMesh(dir / "ball.stl");
    mesh.triangles.resize(mesh.triangles.size() - 1);  // a hole
    const MeshImportReport report = inspectMesh(mesh);
    EXPECT_FALSE(report.closed());
    EXPECT_EQ(report.boundaryEdges, 3u);
    EXPECT_GT(meshToField(mesh, 0.25).grid().activeVoxelCount(), 0u);
}

TEST(MeshImport, OffVariantsWithColoursNormalsAndCommentsImport)
{
    // The cube of side 8 as other programs write it: CGAL's COFF (a colour per vertex), NOFF
    // (normals), comments before and inside, the counts on the keyword's line, faces in colour.
    std::string corners[8], normals[8];
    for (int i = 0; i < 8; ++i) {
        corners[i] = std::to_string(i & 1 ? 4 : -4) + " " + std::to_string(i & 2 ? 4 : -4) + " " +
                     std::to_string(i & 4 ? 4 : -4);
        normals[i] =
            std::string(i & 1 ? "0.57" : "-0.57") + (i & 2 ? " 0.57" : " -0.57") + (i & 4 ? " 0.57" : " -0.57");
    }
    const std::string faces = "4 0 2 3 1\n4 4 5 7 6\n4 0 1 5 4\n4 2 6 7 3\n4 0 4 6 2\n4 1 3 7 5\n";
    std::map<std::string, std::string> files;
    files["coff.off"] = "COFF\n8 6 0\n";
    files["noff.off"] = "NOFF\n8 6 0\n";
    files["comments.off"] = "# written by hand\n\nOFF 8 6 12 # counts on this line\n# the vertices\n";
    for (int i = 0; i < 8; ++i) {
        files["coff.off"] += corners[i] + " 192 192 192 255\n";
        files["noff.off"] += corners[i] + " " + normals[i] + "\n";
        files["comments.off"] += corners[i] + "   # corner " + std::to_string(i) + "\n";
    }
    files["coff.off"] += faces;
    files["noff.off"] += faces;
    files["comments.off"] += "# the faces, in colour\n";
    std::istringstream lines(faces);
    for (std::string line; std::getline(lines, line);) files["comments.off"] += line + " 1.0 0.5 0.25\n";
    test::TempDir dir;
    for (const auto& [name, text] : files) {
        std::ofstream(dir / name) << text;
        const TriangleMesh mesh = readMesh(dir / name);
        EXPECT_EQ(mesh.triangles.size(), 12u) << name;
        EXPECT_TRUE(inspectMesh(mesh).closed()) << name;
        EXPECT_NEAR(std::abs(test::meshVolume(mesh)), 512.0, 1e-9) << name;
    }
}

TEST(MeshImport, BadFilesAreRefusedNamingTheFile)
{
    test::TempDir dir;
    std::ofstream(dir / "huge.off") << "OFF\n100000000 100000000 0\n0 0 0\n";
    std::ofstream(dir / "cut.off") << "OFF\n4 1 0\n0 0 0\n1 0 0\n";
    std::ofstream(dir / "index.off") << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n";
    std::ofstream(dir / "junk.stl") << "solid junk\nthis is not a facet\n";
    std::ofstream(dir / "empty.obj") << "# nothing\n";
    std::ofstream(dir / "binary.off") << "OFF BINARY\n";
    std::ofstream(dir / "four.off") << "4OFF\n1 0 0\n0 0 0 1\n";
    std::ofstream(dir / "word.off") << "OFF\n3 1 0\n0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n";
    const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    std::ofstream(dir / "beyond.obj") << triangle << "f 1 2 4\n";
    std::ofstream(dir / "zero.obj") << triangle << "f 0 1 2\n";
    std::ofstream(dir / "back.obj") << triangle << "f -1 -2 -4\n";
    std::ofstream(dir / "slashes.obj") << triangle << "vt 0 0\nf 1/1 2/1 x/1\n";
    std::ofstream(dir / "nan.obj") << "v 0 0 nan\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    const std::string plyHead = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                                "0 0 0\n1 0 0\n0 1 0\n";
    std::ofstream(dir / "index.ply") << plyHead << "3 0 1 3\n";
    std::ofstream(dir / "list.ply") << plyHead << "200 0 1 2\n";
    std::ofstream(dir / "nox.ply") << "ply\nformat ascii 1.0\nelement vertex 1\nproperty float y\nend_header\n0\n";
    for (const char* name : {"huge.off", "cut.off", "index.off", "junk.stl", "empty.obj", "missing.ply", "ball.xyz",
                             "binary.off", "four.off", "word.off", "beyond.obj", "zero.obj", "back.obj", "slashes.obj",
                             "nan.obj", "index.ply", "list.ply", "nox.ply"}) {
        try {
            readMesh(dir / name);
            ADD_FAILURE() << "no error for " << name;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
        }
    }
}

TEST(MeshImport, TruncatedPlyAndStlFilesAreRefused)
{
    test::TempDir dir;
    vtkNew<vtkSphereSource> sphere;
    vtkNew<vtkTriangleFilter> triangles;
    triangles->SetInputConnection(sphere->GetOutputPort());
    vtkNew<vtkPLYWriter> ply;
    ply->SetInputConnection(triangles->GetOutputPort());
    ply->SetFileName((dir / "ball.ply").c_str());
    ply->Write();
    ply->SetFileTypeToASCII();
    ply->SetFileName((dir / "text.ply").c_str());
    ply->Write();
    vtkNew<vtkSTLWriter> stl;
    stl->SetInputConnection(triangles->GetOutputPort());
    stl->SetFileTypeToBinary();
    stl->SetFileName((dir / "ball.stl").c_str());
    stl->Write();
    for (const char* name : {"ball.ply", "text.ply", "ball.stl"}) {
        ASSERT_NO_THROW(readMesh(dir / name)) << name;
        const std::string bytes = test::fileBytes(dir / name);
        for (const double share : {0.1, 0.5, 0.9}) {
            const std::string cut = "cut_" + std::to_string(int(share * 100)) + "_" + name;
            std::ofstream(dir / cut, std::ios::binary) << bytes.substr(0, std::size_t(share * double(bytes.size())));
            try {
                readMesh(dir / cut);
                ADD_FAILURE() << cut << " was read";
            } catch (const InputError& e) {
                EXPECT_NE(std::string(e.what()).find(cut), std::string::npos) << e.what();
            }
        }
    }
}

/// Byte offsets of a binary PLY's face lists (uchar count, int indices), after its vertices.
std::size_t firstFaceOffset(const std::string& bytes, std::size_t vertexBytes, std::size_t vertices)
{
    return bytes.find("end_header\n") + 11 + vertexBytes * vertices;
}

TEST(MeshImport, BinaryPlyFacesNamingNoVertexOrHugeListsAreRefused)
{
    test::TempDir dir;
    TriangleMesh tetra;
    tetra.positions.assign({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
    tetra.triangles.assign({{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}});
    writeMesh(tetra, dir / "tetra.ply");
    ASSERT_EQ(readMesh(dir / "tetra.ply").triangles.size(), 4u);
    const std::string bytes = test::fileBytes(dir / "tetra.ply");
    const std::size_t face = firstFaceOffset(bytes, 12, 4);
    ASSERT_EQ(bytes[face], char(3));
    std::map<std::string, std::string> damaged{{"index.ply", bytes}, {"negative.ply", bytes}, {"list.ply", bytes}};
    damaged["index.ply"][face + 1 + 4 * 2] = char(4);            // a vertex past the last
    damaged["negative.ply"][face + 1 + 4 * 2 + 3] = char(0x80);  // a negative index
    damaged["list.ply"][face] = char(250);                       // a list longer than the file
    for (const auto& [name, content] : damaged) {
        std::ofstream(dir / name, std::ios::binary) << content;
        try {
            readMesh(dir / name);
            ADD_FAILURE() << name << " was read";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
        }
    }
}

TEST(MeshImport, MeshToFieldReportsProgressAndStopsWhenAsked)
{
    const TriangleMesh mesh = meshLevelSet(makeSphere(20.0, 0.5));
    test::ProgressLog log;
    meshToField(mesh, 0.25, log.callback());
    EXPECT_GE(log.fractions().size(), 2u);
    test::ProgressLog stop(0);
    EXPECT_THROW(meshToField(mesh, 0.25, stop.callback()), Cancelled);
}

}  // namespace
}  // namespace sculpt
