// SPDX-License-Identifier: Apache-2.0
// The block mesher on analytic shapes, after random local edits, and against OpenVDB and VTK.

#include "core/local/sphere_stamp.h"
#include "core/mesh/field_measures.h"
#include "core/mesh/incremental_mesher.h"
#include "core/primitives/analytic_shapes.h"
#include "tests/support/mesh_checks.h"
#include "tests/support/progress_log.h"
#include "tests/support/reference_mesher.h"

#include <gtest/gtest.h>
#include <vtkFloatArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkMassProperties.h>
#include <vtkNew.h>
#include <vtkPointData.h>

#include <random>
#include <set>

namespace sculpt {
namespace {

constexpr double kPi = 3.14159265358979323846;
using test::meshTopology;

class SphereMesh : public ::testing::TestWithParam<double> {};

TEST_P(SphereMesh, IsClosedAccurateAndOnTheSurface)
{
    const double r = GetParam(), h = 1.0;
    const TriangleMesh mesh = meshLevelSet(makeSphere(r, h));
    const test::MeshTopology t = meshTopology(mesh);
    EXPECT_TRUE(t.closedManifold()) << t.boundaryEdges << " boundary, " << t.nonManifoldEdges << " non-manifold, "
                                    << t.misorientedEdges << " misoriented";
    EXPECT_EQ(t.eulerCharacteristic(), 2);
    double worst = 0.0;
    for (const auto& p : mesh.positions) {
        worst = std::max(worst, std::abs(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - r));
    }
    EXPECT_LT(worst, 0.1 * h);
    EXPECT_NEAR(test::meshArea(mesh), 4.0 * kPi * r * r, 0.01 * 4.0 * kPi * r * r);
    EXPECT_NEAR(test::meshVolume(mesh), 4.0 / 3.0 * kPi * r * r * r, 0.01 * 4.0 / 3.0 * kPi * r * r * r);
    for (size_t i = 0; i < mesh.positions.size(); i += 97) {  // normals point outwards
        const auto& p = mesh.positions[i];
        const auto& n = mesh.normals[i];
        EXPECT_GT((p[0] * n[0] + p[1] * n[1] + p[2] * n[2]) / r, 0.99);
    }
}

INSTANTIATE_TEST_SUITE_P(RadiusVoxels, SphereMesh, ::testing::Values(8.0, 13.7, 30.0, 64.0, 100.0),
                         [](const auto& test) { return "r" + std::to_string(int(test.param)); });

TEST(IncrementalMesher, TorusIsClosedWithEulerZero)
{
    const double R = 24.0, r = 8.0;
    const TriangleMesh mesh = meshLevelSet(makeTorus(R, r, 1.0));
    const test::MeshTopology t = meshTopology(mesh);
    EXPECT_TRUE(t.closedManifold());
    EXPECT_EQ(t.eulerCharacteristic(), 0);
    EXPECT_NEAR(test::meshVolume(mesh), 2.0 * kPi * kPi * R * r * r, 0.01 * 2.0 * kPi * kPi * R * r * r);
    EXPECT_NEAR(test::meshArea(mesh), 4.0 * kPi * kPi * R * r, 0.01 * 4.0 * kPi * kPi * R * r);
}

TEST(IncrementalMesher, BoxIsClosedWithEulerTwo)
{
    const double a = 10.3;  // faces between voxel planes
    const TriangleMesh mesh = meshLevelSet(makeBox(a, 1.0));
    const test::MeshTopology t = meshTopology(mesh);
    EXPECT_TRUE(t.closedManifold());
    EXPECT_EQ(t.eulerCharacteristic(), 2);
    EXPECT_NEAR(test::meshVolume(mesh), 8.0 * a * a * a, 0.01 * 8.0 * a * a * a);
}

TEST(IncrementalMesher, EveryBlockSizeGivesTheSameSurface)
{
    const FieldImage torus = makeTorus(20.0, 7.0, 1.0);
    const TriangleMesh reference = meshLevelSet(torus, 16);
    for (int B : {8, 32}) {
        const TriangleMesh mesh = meshLevelSet(torus, B);
        EXPECT_EQ(mesh.triangles.size(), reference.triangles.size()) << B;
        EXPECT_EQ(mesh.positions.size(), reference.positions.size()) << B;
        EXPECT_NEAR(test::meshVolume(mesh), test::meshVolume(reference), 1e-9 * test::meshVolume(reference)) << B;
    }
}

void expectIdentical(const TriangleMesh& a, const TriangleMesh& b)
{
    ASSERT_EQ(a.positions.size(), b.positions.size());
    ASSERT_EQ(a.triangles.size(), b.triangles.size());
    EXPECT_TRUE(a.positions == b.positions);
    EXPECT_TRUE(a.normals == b.normals);
    EXPECT_TRUE(a.triangles == b.triangles);
}

TEST(IncrementalMesher, RandomEditsMatchAFullRemesh)
{
    const unsigned seed = 20261122;
    std::mt19937 random(seed);
    FieldImage field = makeSphere(24.0, 1.0);
    IncrementalMesher mesher;
    mesher.rebuild(field);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), radius(1.5, 5.0);
    for (int edit = 0; edit < 200; ++edit) {
        openvdb::Vec3d direction(unit(random), unit(random), unit(random));
        direction.normalize();
        const openvdb::Vec3d centre = direction * (24.0 + 3.0 * unit(random));
        const auto mode = random() % 2 ? CsgMode::Add : CsgMode::Carve;
        const DirtyRegion dirty = stampSphere(field, centre, radius(random), mode);
        const std::uint64_t before = mesher.version();
        const std::size_t remeshed = mesher.update(field, dirty);
        EXPECT_LE(remeshed, 8 * dirty.leafCount()) << "seed " << seed << " edit " << edit;
        const auto changes = mesher.changesSince(before);
        EXPECT_LE(changes.updated.size() + changes.removed.size(), remeshed);
    }
    IncrementalMesher fresh;
    fresh.rebuild(field);
    expectIdentical(mesher.weldedMesh(), fresh.weldedMesh());
    const test::MeshTopology t = meshTopology(mesher.weldedMesh());
    EXPECT_TRUE(t.closedManifold()) << "seed " << seed;
}

TEST(IncrementalMesher, AViewerFarBehindIsToldEveryChangeAfterItsLogIsCompacted)
{
    std::mt19937 random(20261204);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    FieldImage field = makeSphere(20.0, 1.0);
    IncrementalMesher mesher;
    mesher.rebuild(field);
    const auto atStart = mesher.blocks();
    const std::uint64_t start = mesher.version();
    std::size_t logged = 0, lastRemeshed = 0;
    std::uint64_t beforeLast = start;
    for (int edit = 0; edit < 600; ++edit) {  // far more origins than 2 x blocks + 4096: compacted
        openvdb::Vec3d direction(unit(random), unit(random), unit(random));
        const openvdb::Vec3d centre = direction.unit() * (20.0 + 2.0 * unit(random));
        beforeLast = mesher.version();
        lastRemeshed = mesher.update(field, stampSphere(field, centre, 3.0, edit % 2 ? CsgMode::Add : CsgMode::Carve));
        logged += lastRemeshed;
    }
    ASSERT_GT(logged, 2 * mesher.blocks().size() + 4096);
    const auto changes = mesher.changesSince(start);
    const std::set<openvdb::Coord> updated(changes.updated.begin(), changes.updated.end());
    const std::set<openvdb::Coord> removed(changes.removed.begin(), changes.removed.end());
    for (const auto& [origin, mesh] : mesher.blocks()) {
        if (mesh.version > start) {
            EXPECT_TRUE(updated.count(origin)) << origin;
        }
        EXPECT_FALSE(removed.count(origin)) << origin;
    }
    for (const auto& [origin, mesh] : atStart) {
        if (!mesher.blocks().count(origin)) {
            EXPECT_TRUE(removed.count(origin)) << origin;
        }
    }
    const auto last = mesher.changesSince(beforeLast);  // a viewer one update behind: just that one
    EXPECT_LE(last.updated.size() + last.removed.size(), lastRemeshed);
    EXPECT_TRUE(mesher.changesSince(mesher.version()).updated.empty());
    const std::uint64_t version = mesher.version();
    mesher.update(field, DirtyRegion());
    EXPECT_EQ(mesher.version(), version);  // nothing dirty, nothing new
}

TEST(IncrementalMesher, OneEditRemeshesOnlyNearbyBlocks)
{
    FieldImage field = makeSphere(60.0, 1.0);
    IncrementalMesher mesher;
    mesher.rebuild(field);
    const std::size_t total = mesher.blocks().size();
    const std::uint64_t before = mesher.version();
    const DirtyRegion dirty = stampSphere(field, {60.0, 0.0, 0.0}, 4.0, CsgMode::Add);
    mesher.update(field, dirty);
    const auto changes = mesher.changesSince(before);
    EXPECT_GT(changes.updated.size(), 0u);
    EXPECT_LT(changes.updated.size(), total / 20);
    for (const auto& origin : changes.updated) {
        EXPECT_LT((origin.asVec3d() - openvdb::Vec3d(60.0, 0.0, 0.0)).length(), 4.0 + 3.0 + 2.0 * 16 * std::sqrt(3.0));
    }
}

TEST(IncrementalMesher, MemoryHoldsTheMeshesAndLittleMore)
{
    FieldImage field = makeSphere(20.0, 1.0);
    IncrementalMesher mesher;
    mesher.rebuild(field);
    // 12 bytes a position, 12 a normal, 8 a key, 12 a triangle: what the blocks must hold.
    std::size_t vertices = 0, triangles = 0;
    for (const auto& [origin, mesh] : mesher.blocks()) {
        vertices += mesh.positions.size();
        triangles += mesh.triangles.size();
    }
    ASSERT_EQ(triangles, mesher.triangleCount());
    const std::size_t needed = vertices * (12 + 12 + 8) + triangles * 12;
    EXPECT_GE(mesher.memoryBytes(), needed);
    EXPECT_LE(mesher.memoryBytes(), 2 * needed) << "vector growth should cost at most twice the data";
    // A sphere of radius 20 voxels: about 8 pi r^2 / 1 triangles (two per voxel of area).
    EXPECT_GT(triangles, std::size_t(4.0 * M_PI * 400.0));
}

TEST(IncrementalMesher, CarvedAwayBlocksAreDropped)
{
    FieldImage field = makeSphere(6.0, 1.0);
    IncrementalMesher mesher;
    mesher.rebuild(field);
    ASSERT_GT(mesher.triangleCount(), 0u);
    const std::uint64_t before = mesher.version();
    mesher.update(field, stampSphere(field, {0.0, 0.0, 0.0}, 12.0, CsgMode::Carve));
    EXPECT_EQ(mesher.triangleCount(), 0u);
    EXPECT_TRUE(mesher.blocks().empty());
    EXPECT_FALSE(mesher.changesSince(before).removed.empty());
    EXPECT_EQ(mesher.memoryBytes(), 0u);  // dropped blocks give their memory back
}

TEST(IncrementalMesher, AgreesWithOpenVdbVolumeToMesh)
{
    for (const FieldImage& field : {makeSphere(20.0, 1.0), makeTorus(24.0, 9.0, 1.0)}) {
        const TriangleMesh ours = meshLevelSet(field);
        const TriangleMesh theirs = test::meshWithVolumeToMesh(field);
        EXPECT_NEAR(test::meshArea(ours), test::meshArea(theirs), 0.005 * test::meshArea(theirs));
        EXPECT_NEAR(test::meshVolume(ours), test::meshVolume(theirs), 0.005 * test::meshVolume(theirs));
    }
}

/// Area and volume of vtkFlyingEdges3D's iso-surface of the dense copy of a grid.
std::pair<double, double> flyingEdgesMeasures(const FieldImage& field)
{
    openvdb::CoordBBox box = field.grid().evalActiveVoxelBoundingBox();
    box.expand(1);
    vtkNew<vtkImageData> image;
    const openvdb::Coord dim = box.dim();
    image->SetDimensions(dim.x(), dim.y(), dim.z());
    image->SetSpacing(field.voxelSize(), field.voxelSize(), field.voxelSize());
    const openvdb::Vec3d origin = field.grid().transform().indexToWorld(box.min());
    image->SetOrigin(origin.x(), origin.y(), origin.z());
    vtkNew<vtkFloatArray> values;
    values->SetNumberOfTuples(vtkIdType(box.volume()));
    auto acc = field.grid().getConstAccessor();
    vtkIdType i = 0;
    for (int z = box.min().z(); z <= box.max().z(); ++z)  // VTK: x varies fastest
        for (int y = box.min().y(); y <= box.max().y(); ++y)
            for (int x = box.min().x(); x <= box.max().x(); ++x) values->SetValue(i++, acc.getValue({x, y, z}));
    image->GetPointData()->SetScalars(values);
    vtkNew<vtkFlyingEdges3D> contour;
    contour->SetInputData(image);
    contour->SetValue(0, 0.0);
    vtkNew<vtkMassProperties> mass;
    mass->SetInputConnection(contour->GetOutputPort());
    mass->Update();
    return {mass->GetSurfaceArea(), mass->GetVolume()};
}

TEST(IncrementalMesher, AgreesWithVtkFlyingEdges)
{
    for (const FieldImage& field : {makeSphere(20.0, 0.5), makeTorus(12.0, 4.5, 0.5)}) {
        const TriangleMesh ours = meshLevelSet(field);
        const auto [area, volume] = flyingEdgesMeasures(field);
        EXPECT_NEAR(test::meshArea(ours), area, 0.005 * area);
        EXPECT_NEAR(test::meshVolume(ours), volume, 0.005 * volume);
    }
}

TEST(IncrementalMesher, ARebuildReportsProgressToTheEndAndStopsWhenAsked)
{
    const FieldImage field = makeSphere(30.0, 0.5);
    test::ProgressLog log;
    IncrementalMesher mesher;
    mesher.rebuild(field, log.callback());
    EXPECT_GE(log.fractions().size(), 10u);
    EXPECT_TRUE(log.monotone());
    EXPECT_EQ(log.fractions().back(), 1.0);
    EXPECT_EQ(mesher.weldedMesh().triangles.size(), meshLevelSet(field).triangles.size());
    test::ProgressLog stop(2);
    IncrementalMesher stopped;
    EXPECT_THROW(stopped.rebuild(field, stop.callback()), Cancelled);
    EXPECT_EQ(stop.fractions().size(), 3u);
}

}  // namespace
}  // namespace sculpt
