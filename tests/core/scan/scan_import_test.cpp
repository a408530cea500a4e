// SPDX-License-Identifier: Apache-2.0
// Importing scans (core/scan_volume.h, core/scan_to_level_set.h): every format, world placement,
// agreement with VTK on a real MRI, and refusal of bad files. DICOM: dicom_series_test.cpp.

#include "core/base/errors.h"
#include "core/field/grid_checksum.h"
#include "core/mesh/field_measures.h"
#include "core/mesh/incremental_mesher.h"
#include "core/motion/surface_flows.h"
#include "core/scan/largest_component.h"
#include "core/scan/scan_readers.h"
#include "core/scan/scan_to_level_set.h"
#include "tests/support/file_bytes.h"
#include "tests/support/mesh_checks.h"
#include "tests/support/progress_log.h"
#include "tests/support/synthetic_scan.h"
#include "tests/support/temp_dir.h"

#include <gtest/gtest.h>
#include <openvdb/tools/FastSweeping.h>
#include <tbb/global_control.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkMassProperties.h>
#include <vtkMatrix4x4.h>
#include <vtkMetaImageWriter.h>
#include <vtkNIFTIImageReader.h>
#include <vtkNIFTIImageWriter.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleFilter.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>

namespace sculpt {
namespace {

using test::expectBallAt;
using test::sampledImage;
using test::sphereOf;
using test::SyntheticBall;

const char* kMri = "/usr/share/mricron/templates/ch2bet.nii.gz";

/// MetaImage, uncompressed; a .mhd header keeps its samples in a .raw beside it (read raw too).
void writeMetaImage(vtkImageData* image, const std::filesystem::path& path)
{
    vtkNew<vtkMetaImageWriter> writer;
    writer->SetInputData(image);
    writer->SetFileName(path.c_str());
    if (path.extension() == ".mhd")
        writer->SetRAWFileName(path.parent_path().append(path.stem().string() + ".raw").c_str());
    writer->SetCompression(false);
    writer->Write();
}

TEST(ScanImport, NiftiMetaImageNrrdAndRawKeepSpacingAndOrigin)
{
    test::TempDir dir;
    const SyntheticBall ball;
    const auto image = ball.image();
    {
        vtkNew<vtkNIFTIImageWriter> writer;
        writer->SetInputData(image);
        writer->SetFileName((dir / "ball.nii.gz").c_str());
        // NIfTI keeps placement in its qform: put the origin there, as scanners do.
        vtkNew<vtkMatrix4x4> qform;
        for (int a = 0; a < 3; ++a) qform->SetElement(a, 3, ball.origin[a]);
        writer->SetQFormMatrix(qform);
        auto shifted = vtkSmartPointer<vtkImageData>::New();
        shifted->ShallowCopy(image);
        shifted->SetOrigin(0.0, 0.0, 0.0);
        writer->SetInputData(shifted);
        writer->Write();
        // The qform places it in RAS: in the documents' LPS, x and y are negated.
        SyntheticBall inLps = ball;
        inLps.centre = openvdb::Vec3d(-ball.centre.x(), -ball.centre.y(), ball.centre.z());
        expectBallAt(readScan(dir / "ball.nii.gz"), inLps, "NIfTI");
    }
    {
        writeMetaImage(image, dir / "ball.mhd");
        expectBallAt(readScan(dir / "ball.mhd"), ball, "MetaImage");
    }
    {
        std::ofstream header(dir / "ball.nhdr");
        header << "NRRD0004\ntype: short\ndimension: 3\nsizes: " << ball.dims.x() << " " << ball.dims.y() << " "
               << ball.dims.z() << "\nspacings: 1 1 2\nencoding: raw\nendian: little\nspace origin: ("
               << ball.origin.x() << "," << ball.origin.y() << "," << ball.origin.z() << ")\ndata file: ball.raw\n";
        header.close();
        const ScanVolume nrrd = readScan(dir / "ball.nhdr");
        EXPECT_EQ(nrrd.dims(), ball.dims);
        const FieldImage field = scanToLevelSet(nrrd, 100.0, 1.0);
        EXPECT_NEAR(sphereOf(field).first, ball.radius, 0.5) << "NRRD";
    }
    {
        RawLayout layout;
        layout.dims = ball.dims;
        layout.type = "int16";
        layout.spacing = ball.spacing;
        layout.origin = ball.origin;
        expectBallAt(readRawScan(dir / "ball.raw", layout), ball, "raw");
    }
}

/// The largest and the mean difference between a band's values and the distance to the ball.
std::pair<double, double> distanceError(const openvdb::FloatGrid& grid, const SyntheticBall& ball)
{
    double worst = 0.0, sum = 0.0;
    for (auto it = grid.cbeginValueOn(); it; ++it) {
        const double exact = (grid.transform().indexToWorld(it.getCoord()) - ball.centre).length() - ball.radius;
        worst = std::max(worst, std::abs(*it - exact));
        sum += std::abs(*it - exact);
    }
    return {worst, sum / double(grid.activeVoxelCount())};
}

TEST(ScanImport, TheDefaultVoxelSizeStaysWithinSixteenTimesTheCoarsestSpacing)
{
    // Found by the NIfTI fuzz target: the seed ball with the sform's y spacing 1/256. At its
    // smallest spacing the conversion ran past a minute (4096 x 16 x 4096 voxels).
    const ScanVolume scan = readScan(SCULPT_TESTS_DIR "/core/scan/slab_spacing.nii");
    ASSERT_NEAR(scan.spacing(1), 1.0 / 256.0, 1e-9);
    EXPECT_DOUBLE_EQ(nativeVoxelSize(scan), 1.0 / 16.0);
    // The slab is one such voxel thick: no crossing to sample, said at once instead of after minutes.
    const auto [lo, hi] = scan.range();
    EXPECT_THROW(scanToLevelSet(scan, 0.5 * (lo + hi), nativeVoxelSize(scan)), InputError);
}

TEST(ScanImport, BandHoldsTheDistanceToTheSurfaceAcrossTiles)
{
    // The ball spans several of the converter's tiles (32 x 32 x 16 voxels) in every axis.
    test::TempDir dir;
    const SyntheticBall ball;
    writeMetaImage(ball.image(), dir / "ball.mha");
    const ScanVolume scan = readScan(dir / "ball.mha");
    const FieldImage field = scanToLevelSet(scan, 100.0, 1.0);
    const auto& grid = field.grid();
    const auto [worst, mean] = distanceError(grid, ball);
    // OpenVDB's fast sweeping, run on the same band, as the reference for "as exact as".
    const auto [sweepWorst, sweepMean] = distanceError(*openvdb::tools::sdfToSdf(grid), ball);
    EXPECT_LT(worst, 0.25) << "voxels";
    EXPECT_LT(mean, 0.1) << "voxels";
    EXPECT_LE(worst, sweepWorst);  // measured: 0.16 vs 0.38 voxel
    EXPECT_LE(mean, sweepMean);    // 0.060 vs 0.088
    const size_t count = grid.activeVoxelCount();
    EXPECT_DOUBLE_EQ(grid.background(), 3.0);
    EXPECT_GT(count, size_t(6 * 4 * M_PI * ball.radius * ball.radius * 0.9)) << "a band 3 voxels deep each side";

    // Tiles are converted in parallel but written in order: one thread gives the same bits.
    tbb::global_control oneThread(tbb::global_control::max_allowed_parallelism, 1);
    EXPECT_EQ(gridChecksum(scanToLevelSet(scan, 100.0, 1.0).grid()), gridChecksum(grid));
}

TEST(ScanImport, OtsuSplitsTheTwoMaterials)
{
    test::TempDir dir;
    const SyntheticBall ball;
    writeMetaImage(ball.image(), dir / "ball.mha");
    EXPECT_FALSE(readScan(dir / "ball.mha").twoValued()) << "a ramp across the surface";
    const double iso = readScan(dir / "ball.mha").otsuThreshold();
    EXPECT_GT(iso, 20.0);
    EXPECT_LT(iso, 180.0);
}

TEST(ScanImport, CropSmoothAndLargestComponent)
{
    test::TempDir dir;
    const SyntheticBall ball;
    writeMetaImage(ball.image(), dir / "ball.mha");
    const ScanVolume scan = readScan(dir / "ball.mha");
    // The lower half in z (samples 0..10 of 22): a capped half ball, still placed in the world.
    const FieldImage half =
        scanToLevelSet(scan.cropped(openvdb::CoordBBox(openvdb::Coord(0), openvdb::Coord(39, 39, 10))), 100.0, 1.0);
    const openvdb::CoordBBox box = half.grid().evalActiveVoxelBoundingBox();
    EXPECT_LT(half.grid().transform().indexToWorld(box.max()).z(), ball.origin.z() + 2 * 10 + 4);
    const double halfBall = 2.0 / 3.0 * M_PI * std::pow(ball.radius, 3);
    EXPECT_NEAR(test::meshVolume(meshLevelSet(half)), halfBall, 0.06 * halfBall);
    // Smoothing keeps a ball a ball.
    EXPECT_NEAR(sphereOf(scanToLevelSet(scan.smoothed(1.0), 100.0, 1.0)).first, ball.radius, 0.6);
    EXPECT_THROW(scan.cropped(openvdb::CoordBBox(openvdb::Coord(100), openvdb::Coord(120))), InputError);
}

/// A mask (0/1 bytes) of a ball of radius 20 voxels, written as MetaImage.
struct ByteMaskBall {
    double radius = 20.0;
    openvdb::Vec3d centre{24.3, 24.6, 24.1};
    ScanVolume scan(const std::filesystem::path& file) const
    {
        vtkNew<vtkImageData> mask;
        mask->SetDimensions(50, 50, 50);
        mask->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
        for (int k = 0; k < 50; ++k)
            for (int j = 0; j < 50; ++j)
                for (int i = 0; i < 50; ++i)
                    *static_cast<unsigned char*>(mask->GetScalarPointer(i, j, k)) =
                        (openvdb::Vec3d(i, j, k) - centre).length() < radius ? 1 : 0;
        writeMetaImage(mask, file);
        return readScan(file);
    }
    /// Root mean square and largest distance of the mesh's vertices to the true sphere.
    std::pair<double, double> distances(const TriangleMesh& mesh) const
    {
        double sum = 0.0, worst = 0.0;
        for (const std::array<float, 3>& p : mesh.positions) {
            const double d = std::abs((openvdb::Vec3d(p[0], p[1], p[2]) - centre).length() - radius);
            sum += d * d;
            worst = std::max(worst, d);
        }
        return {std::sqrt(sum / double(mesh.positions.size())), worst};
    }
};

// Smoothing blurs a byte mask's staircase in floating point, so the ball keeps its radius (in
// the bytes' own type each blurred sample was rounded: sigma 0.7 eroded the ball by 3.1 voxels,
// sigma 1 left nothing).
TEST(ScanImport, SmoothingAByteMaskKeepsItsShape)
{
    const ByteMaskBall ball;
    test::TempDir dir;
    const ScanVolume scan = ball.scan(dir / "mask.mha");
    EXPECT_TRUE(scan.twoValued());
    EXPECT_DOUBLE_EQ(scan.otsuThreshold(), 0.5) << "the middle of the gap between the two values";
    for (const double sigma : {0.7, 1.0, 2.0}) {
        const auto [r, c] = sphereOf(scanToLevelSet(scan.smoothed(sigma), 0.5, 1.0));
        EXPECT_NEAR(r, ball.radius, 0.25) << "sigma " << sigma;
        EXPECT_LT((c - ball.centre).length(), 0.1) << "sigma " << sigma;
    }
}

// Anti-aliased (Whitaker's constrained flow), the byte mask's voxel terraces relax into the
// sphere they sample: a fifth of their distance to it, and its area, not a tenth more.
TEST(ScanImport, AByteMaskAntiAliasesIntoTheBallItSamples)
{
    const ByteMaskBall ball;
    test::TempDir dir;
    FieldImage field = scanToLevelSet(ball.scan(dir / "mask.mha"), 0.5, 1.0);
    const double sphereArea = 4.0 * M_PI * ball.radius * ball.radius;
    const TriangleMesh terraces = meshLevelSet(field);
    const auto [terraceRms, terraceWorst] = ball.distances(terraces);
    test::ProgressLog log;
    antiAlias(field, kAntiAliasIterations, log.callback());
    EXPECT_TRUE(log.monotone());
    const TriangleMesh smooth = meshLevelSet(field);
    const auto [rms, worst] = ball.distances(smooth);
    // Measured: the terraces 0.22 voxel RMS, 0.57 worst, area +10.4%; anti-aliased 0.04, 0.17, +0.02%.
    EXPECT_GT(terraceRms, 0.15);
    EXPECT_GT(test::meshArea(terraces), 1.05 * sphereArea);
    EXPECT_LT(rms, 0.1);
    EXPECT_LT(worst, 0.3);
    EXPECT_NEAR(test::meshArea(smooth), sphereArea, 0.01 * sphereArea);
    EXPECT_TRUE(test::meshTopology(smooth).closedManifold());
}

TEST(ScanImport, LargestComponentDropsIslandsAndFillsCavities)
{
    // A hollow ball (radius 14, cavity 8, the wall 6 voxels: wider than the band), a ball floating
    // in the cavity (3), and one beside it (5) within the big ball's band (a 3-voxel gap).
    const openvdb::Vec3d centre(24.0, 24.0, 24.0), beside(46.0, 24.0, 24.0);
    const auto sdf = [&](const openvdb::Vec3d& p) {
        const double r = (p - centre).length();
        return std::min({std::max(r - 14.0, 8.0 - r), r - 3.0, (p - beside).length() - 5.0});
    };
    test::TempDir dir;
    writeMetaImage(sampledImage(openvdb::Coord(56, 48, 48), openvdb::Vec3d(1.0), openvdb::Vec3d(0.0), sdf),
                   dir / "pieces.mha");
    FieldImage field = scanToLevelSet(readScan(dir / "pieces.mha"), 100.0, 1.0);
    EXPECT_EQ(test::meshTopology(meshLevelSet(field)).eulerCharacteristic(), 8) << "four sphere-like surfaces";

    // Asked to stop at its last report, it leaves the field as it was.
    const std::uint64_t before = gridChecksum(field.grid());
    test::ProgressLog stop(2);
    EXPECT_THROW(keepLargestComponent(field, stop.callback()), Cancelled);
    EXPECT_EQ(gridChecksum(field.grid()), before);
    test::ProgressLog log;
    const LargestComponentReport report = keepLargestComponent(field, log.callback());
    EXPECT_EQ(log.fractions().size(), 3u);
    EXPECT_TRUE(log.monotone());
    EXPECT_EQ(report.islandsDropped, 1u);
    EXPECT_EQ(report.cavitiesFilled, 1u) << "with the island in it";
    const TriangleMesh mesh = meshLevelSet(field);
    EXPECT_TRUE(test::meshTopology(mesh).closedManifold());
    EXPECT_EQ(test::meshTopology(mesh).eulerCharacteristic(), 2) << "one closed shell";
    const double ball = 4.0 / 3.0 * M_PI * std::pow(14.0, 3);
    EXPECT_NEAR(test::meshVolume(mesh), ball, 0.02 * ball);
    const auto& values = field.grid().tree();
    EXPECT_GT(values.getValue(openvdb::Coord(46, 24, 24)), 0.0f) << "the island beside is outside";
    EXPECT_LT(values.getValue(openvdb::Coord(24, 24, 24)), 0.0f) << "the cavity and its island are inside";
    EXPECT_LT(values.getValue(openvdb::Coord(30, 24, 24)), 0.0f);
    const LargestComponentReport again = keepLargestComponent(field);
    EXPECT_EQ(again.islandsDropped + again.cavitiesFilled, 0u) << "one piece left";
}

TEST(ScanImport, CoarseVoxelSizeAveragesNoiseInsteadOfAliasingIt)
{
    // A ball of radius 12 sampled every 0.5, its surface jittered by up to 1.5 (3 samples) at
    // every sample, imported at voxel size 2.
    const openvdb::Vec3d centre(16.0, 16.0, 16.0);
    std::mt19937 random(11);
    std::uniform_real_distribution<double> noise(-1.5, 1.5);
    const auto sdf = [&](const openvdb::Vec3d& p) { return (p - centre).length() - 12.0 + noise(random); };
    test::TempDir dir;
    writeMetaImage(sampledImage(openvdb::Coord(65), openvdb::Vec3d(0.5), openvdb::Vec3d(0.0), sdf), dir / "noisy.mha");
    const ScanVolume scan = readScan(dir / "noisy.mha");
    const auto filtered = scan.antiAliased(2.0);
    ASSERT_TRUE(filtered.has_value());
    EXPECT_FALSE(scan.antiAliased(0.5).has_value()) << "nothing to filter at the native size";
    const double sphereArea = 4.0 * M_PI * 12.0 * 12.0;
    const double aliased = test::meshArea(meshLevelSet(scanToLevelSet(scan, 100.0, 2.0))) / sphereArea - 1.0;
    const double smooth = test::meshArea(meshLevelSet(scanToLevelSet(*filtered, 100.0, 2.0))) / sphereArea - 1.0;
    EXPECT_GT(aliased, 0.1) << "point samples of the noise: a rough surface";  // measured +25%
    EXPECT_NEAR(smooth, 0.0, 0.05) << "filtered: the ball";                    // measured -3.0%
    EXPECT_NEAR(sphereOf(scanToLevelSet(*filtered, 100.0, 2.0)).first, 12.0, 1.0) << "within half a voxel";
}

TEST(ScanImport, BadScansAreRefusedNamingTheFile)
{
    test::TempDir dir;
    const SyntheticBall ball;
    vtkNew<vtkNIFTIImageWriter> writer;
    writer->SetInputData(ball.image());
    writer->SetFileName((dir / "ball.nii").c_str());
    writer->Write();
    const auto expectError = [](const std::function<void()>& f, const std::string& text) {
        try {
            f();
            ADD_FAILURE() << "no error, expected " << text;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
        }
    };
    // Truncated: half the samples missing.
    std::filesystem::copy_file(dir / "ball.nii", dir / "cut.nii");
    std::filesystem::resize_file(dir / "cut.nii", std::filesystem::file_size(dir / "ball.nii") / 2);
    expectError([&] { readScan(dir / "cut.nii"); }, "cut.nii");
    // Garbage.
    std::ofstream(dir / "junk.nii") << "this is not a NIfTI file at all, not even close to one";
    expectError([&] { readScan(dir / "junk.nii"); }, "junk.nii");
    // A header claiming absurd dimensions: refused before allocating.
    std::ofstream(dir / "huge.mhd") << "ObjectType = Image\nNDims = 3\nDimSize = 100000 100000 100000\n"
                                       "ElementType = MET_SHORT\nElementDataFile = ball.raw\n";
    expectError([&] { readScan(dir / "huge.mhd"); }, "huge.mhd");
    RawLayout layout;
    layout.dims = openvdb::Coord(400, 400, 400);
    std::ofstream(dir / "small.raw") << "tiny";
    expectError([&] { readRawScan(dir / "small.raw", layout); }, "truncated");
    expectError([&] { readScan(dir / "ball.xyz"); }, "ball.xyz");
    const ScanVolume scan = readScan(dir / "ball.nii");
    expectError([&] { scanToLevelSet(scan, 500.0, 1.0); }, "outside the samples' range");
}

TEST(ScanImport, TruncatedScansAndMissingDataFilesAreRefused)
{
    test::TempDir dir;
    const auto ball = [](const openvdb::Vec3d& p) { return (p - openvdb::Vec3d(8.0)).length() - 5.0; };
    writeMetaImage(sampledImage(openvdb::Coord(16), openvdb::Vec3d(1.0), openvdb::Vec3d(0.0), ball), dir / "ball.mha");
    {  // NRRD by hand: 16^3 bytes, a ball of 200 in 0
        std::ofstream nrrd(dir / "ball.nrrd", std::ios::binary);
        nrrd << "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 16 16 16\nencoding: raw\n\n";
        for (int z = 0; z < 16; ++z)
            for (int y = 0; y < 16; ++y)
                for (int x = 0; x < 16; ++x) nrrd.put(ball(openvdb::Vec3d(x, y, z)) < 0.0 ? char(200) : char(0));
    }
    {
        vtkNew<vtkNIFTIImageWriter> writer;
        writer->SetInputData(sampledImage(openvdb::Coord(16), openvdb::Vec3d(1.0), openvdb::Vec3d(0.0), ball));
        writer->SetFileName((dir / "ball.nii.gz").c_str());
        writer->Write();
        writer->SetFileName((dir / "ball.nii").c_str());
        writer->Write();
    }
    for (const char* name : {"ball.mha", "ball.nrrd", "ball.nii", "ball.nii.gz"}) {
        ASSERT_NO_THROW(readScan(dir / name)) << name;
        const std::string bytes = test::fileBytes(dir / name);
        for (const double share : {0.1, 0.5, 0.9}) {
            const std::string cut = std::string("cut_") + std::to_string(int(share * 100)) + "_" + name;
            std::ofstream(dir / cut, std::ios::binary) << bytes.substr(0, std::size_t(share * double(bytes.size())));
            try {
                readScan(dir / cut);
                ADD_FAILURE() << cut << " was read";
            } catch (const InputError& e) {
                EXPECT_NE(std::string(e.what()).find(cut), std::string::npos) << e.what();
            }
        }
    }
    std::ofstream(dir / "lost.mhd")
        << "NDims = 3\nDimSize = 16 16 16\nElementType = MET_UCHAR\nElementDataFile = lost.raw\n";
    try {
        readScan(dir / "lost.mhd");
        ADD_FAILURE() << "lost.mhd was read";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("lost.raw does not exist"), std::string::npos) << e.what();
    }
}

TEST(ScanImport, RealMriAgreesWithFlyingEdgesAndMassProperties)
{
    if (!std::filesystem::exists(kMri)) GTEST_SKIP() << kMri << " missing: apt-get install mricron-data";
    for (const double iso : {35.0, 60.0}) {
        vtkNew<vtkNIFTIImageReader> reader;
        reader->SetFileName(kMri);
        vtkNew<vtkFlyingEdges3D> edges;
        edges->SetInputConnection(reader->GetOutputPort());
        edges->SetValue(0, iso);
        vtkNew<vtkTriangleFilter> triangles;
        triangles->SetInputConnection(edges->GetOutputPort());
        vtkNew<vtkMassProperties> mass;
        mass->SetInputConnection(triangles->GetOutputPort());
        mass->Update();

        const ScanVolume scan = readScan(kMri);
        const FieldImage field = scanToLevelSet(scan, iso, nativeVoxelSize(scan));
        const TriangleMesh mesh = meshLevelSet(field);
        EXPECT_TRUE(test::meshTopology(mesh).closedManifold());
        EXPECT_NEAR(test::meshVolume(mesh), std::abs(mass->GetVolume()), 0.02 * std::abs(mass->GetVolume())) << iso;
        EXPECT_NEAR(test::meshArea(mesh), mass->GetSurfaceArea(), 0.02 * mass->GetSurfaceArea()) << iso;
    }
}

}  // namespace
}  // namespace sculpt
