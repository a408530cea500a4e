// SPDX-License-Identifier: Apache-2.0
// The scan kept in a document: the same samples at the same places after a save and a read, the
// same surface imported from it as from the scan itself, sparse where the scan is uniform, and a
// damaged or missing one refused naming the file.

#include "core/base/errors.h"
#include "core/field/grid_checksum.h"
#include "core/io/vdb_file.h"
#include "core/primitives/analytic_shapes.h"
#include "core/scan/kept_scan.h"
#include "core/scan/scan_readers.h"
#include "core/scan/scan_to_level_set.h"
#include "core/scan/vtk_image_scan.h"
#include "tests/support/synthetic_scan.h"
#include "tests/support/temp_dir.h"

#include <gtest/gtest.h>
#include <vtkFloatArray.h>
#include <vtkPointData.h>

#include <cmath>
#include <vector>

namespace sculpt {
namespace {

using openvdb::Vec3d;

/// The synthetic ball's samples on a lattice turned 30 degrees about z, so that the kept grid's
/// map must be a full affine one, not a scale and a translation.
ScanVolume turnedBall(vtkSmartPointer<vtkImageData> image = test::SyntheticBall().image())
{
    openvdb::Mat4d m = openvdb::Mat4d::identity();
    m.setToRotation(openvdb::math::Z_AXIS, M_PI / 6.0);
    m.preScale(Vec3d(1.0, 1.0, 2.0));
    m.setTranslation(Vec3d(-13.0, 7.0, 31.0));
    return makeScan(image, m, "ball.nii");
}

/// Every sample of `a` and `b`, slice by slice: equal.
void expectSameSamples(const ScanVolume& a, const ScanVolume& b)
{
    ASSERT_EQ(a.dims(), b.dims());
    const std::size_t count = std::size_t(a.dims().x()) * std::size_t(a.dims().y());
    std::vector<float> sa(count), sb(count);
    for (int k = 0; k < a.dims().z(); ++k) {
        a.readSlice(k, sa.data());
        b.readSlice(k, sb.data());
        ASSERT_EQ(sa, sb) << "slice " << k;
    }
}

/// A document of a sphere keeping `scan`, written to `path`.
void writeKeeping(const std::filesystem::path& path, openvdb::FloatGrid::Ptr scan)
{
    writeFieldImage(makeSphere(10.0, 1.0), path, VdbCompanions{{std::move(scan)}, {}});
}

TEST(KeptScan, SavedAndReadItIsTheSameScanInTheSamePlace)
{
    test::TempDir dir;
    const ScanVolume scan = turnedBall();
    writeKeeping(dir / "doc.vdb", keptScanGrid(scan, 100.0));
    const ScanVolume kept = readScan(dir / "doc.vdb");
    expectSameSamples(scan, kept);
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            EXPECT_NEAR(kept.worldFromIndex()[r][c], scan.worldFromIndex()[r][c], 1e-12) << r << "," << c;

    // The surface imported from the kept scan is the one the scan itself gives, bit for bit.
    const double h = nativeVoxelSize(scan);
    EXPECT_EQ(gridChecksum(scanToLevelSet(kept, 100.0, h).grid()), gridChecksum(scanToLevelSet(scan, 100.0, h).grid()));

    const VdbDocument document = readVdbDocument(dir / "doc.vdb");
    const KeptScanRecord record = keptScanRecord(*findKeptScan(document.companions.grids));
    EXPECT_EQ(record.lattice.dims, scan.dims());
    EXPECT_EQ(record.source, "ball.nii");
    EXPECT_EQ(record.sampleType, "short");
    ASSERT_TRUE(record.iso.has_value());
    EXPECT_EQ(*record.iso, 100.0);
}

TEST(KeptScan, IsSparseWhereTheScanIsUniformAndHalfOnDiskWhenExact)
{
    test::SyntheticBall small;
    small.dims = openvdb::Coord(128, 128, 64);
    small.centre = small.origin + Vec3d(64.0, 64.0, 64.0);
    const ScanVolume scan = turnedBall(small.image());
    const openvdb::FloatGrid::Ptr grid = keptScanGrid(scan, 100.0);
    const double samples = double(scan.dims().x()) * scan.dims().y() * scan.dims().z();
    // The ball fills a few percent of the box: the background (0) around it is held by no
    // voxel, and the grid costs a fraction of a dense float copy.
    EXPECT_LT(double(grid->activeVoxelCount()), 0.1 * samples);
    EXPECT_LT(double(grid->memUsage()), 0.25 * 4.0 * samples);
    EXPECT_TRUE(grid->saveFloatAsHalf()) << "16-bit samples of 0..200 are exact in half floats";

    // Fractional samples are kept as floats, exactly.
    auto image = test::SyntheticBall().image();
    auto fractional = vtkSmartPointer<vtkFloatArray>::New();
    fractional->SetNumberOfValues(image->GetNumberOfPoints());
    for (vtkIdType n = 0; n < image->GetNumberOfPoints(); ++n)
        fractional->SetValue(n, float(image->GetPointData()->GetScalars()->GetTuple1(n)) * 0.37f + 0.01f);
    image->GetPointData()->SetScalars(fractional);
    const ScanVolume floats = turnedBall(image);
    const openvdb::FloatGrid::Ptr floatGrid = keptScanGrid(floats, 40.0);
    EXPECT_FALSE(floatGrid->saveFloatAsHalf());
    test::TempDir dir;
    writeKeeping(dir / "floats.vdb", floatGrid);
    expectSameSamples(floats, readKeptScan(dir / "floats.vdb"));
}

TEST(KeptScan, ADamagedOrMissingScanIsRefusedNamingTheFile)
{
    test::TempDir dir;
    const ScanVolume scan = turnedBall();
    writeFieldImage(makeSphere(10.0, 1.0), dir / "none.vdb");
    try {
        readKeptScan(dir / "none.vdb");
        FAIL() << "a document keeping no scan gave one";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("none.vdb: keeps no scan"), std::string::npos) << e.what();
    }

    openvdb::FloatGrid::Ptr edited = keptScanGrid(scan, 100.0);
    edited->tree().setValue(openvdb::Coord(20, 20, 10), 999.0f);
    writeKeeping(dir / "edited.vdb", edited);
    EXPECT_THROW(readScan(dir / "edited.vdb"), InputError);

    openvdb::FloatGrid::Ptr huge = keptScanGrid(scan, 100.0);
    huge->insertMeta("sculpt.scan_dims", openvdb::Vec3IMetadata(openvdb::Vec3i(1 << 30, 1 << 30, 4)));
    writeKeeping(dir / "huge.vdb", huge);
    try {
        readScan(dir / "huge.vdb");
        FAIL() << "absurd dimensions were accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("huge.vdb"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace sculpt
