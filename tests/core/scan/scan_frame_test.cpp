// SPDX-License-Identifier: Apache-2.0
// Every scan format lands in the documents' frame, LPS millimetres: one volume with a marker at
// the patient's left-anterior, written as NIfTI (sform; qform only; in micrometres), NRRD (a RAS
// space; an LPS space with the negative directions Slicer writes), MetaImage (a flipped
// TransformMatrix) and a DICOM series, imports with the marker at the same LPS point.

#include "core/base/errors.h"
#include "core/scan/scan_frame.h"
#include "core/scan/scan_readers.h"
#include "core/scan/scan_to_level_set.h"
#include "tests/support/dicom_writer.h"
#include "tests/support/synthetic_scan.h"
#include "tests/support/temp_dir.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace sculpt {
namespace {

using openvdb::Vec3d;
using test::TempDir;

constexpr int kNx = 32, kNy = 32, kNz = 24;
constexpr double kSpacing = 2.0;             // mm
const Vec3d kMarker(24.0, -30.0, 10.0);      // LPS: 24 mm to the left, 30 mm to the front
constexpr double kMarkerRadius = 7.0;        // mm
const Vec3d kRasOrigin(-55.0, -1.0, -13.0);  // of sample (0, 0, 0), in RAS: the marker inside

/// LPS from RAS and back: x and y negated.
Vec3d flipped(const Vec3d& p) { return {-p.x(), -p.y(), p.z()}; }

/// The samples (x fastest) of a file whose sample (i, j, k) lies at `lpsOf(i, j, k)`: 200 in
/// the marker, 0 outside, 100 on its surface.
std::vector<std::int16_t> samples(const std::function<Vec3d(int, int, int)>& lpsOf)
{
    std::vector<std::int16_t> out;
    for (int k = 0; k < kNz; ++k)
        for (int j = 0; j < kNy; ++j)
            for (int i = 0; i < kNx; ++i)
                out.push_back(std::int16_t(test::rampSample((lpsOf(i, j, k) - kMarker).length() - kMarkerRadius)));
    return out;
}

/// A RAS lattice from `origin` along +x, +y, +z: NIfTI's and the RAS NRRD's.
Vec3d rasLattice(const Vec3d& origin, int i, int j, int k) { return flipped(origin + kSpacing * Vec3d(i, j, k)); }

void put(std::string& bytes, std::size_t at, const void* value, std::size_t size)
{
    std::memcpy(bytes.data() + at, value, size);
}

/// A NIfTI-1 file of int16 samples: placed by an sform (`sform`) or by a qform of no rotation,
/// with the RAS `origin` and kSpacing, both scaled by `unitsPerMm` and in xyzt_units `units`.
void writeNifti(const std::filesystem::path& path, const Vec3d& origin, bool sform, int units, double unitsPerMm)
{
    std::string bytes(352, '\0');
    const std::int32_t header = 348;
    put(bytes, 0, &header, 4);
    const std::int16_t dim[8] = {3, kNx, kNy, kNz, 1, 1, 1, 1};
    put(bytes, 40, dim, sizeof dim);
    const std::int16_t type[2] = {4, 16};  // DT_INT16, 16 bits
    put(bytes, 70, type, sizeof type);
    const float step = float(kSpacing * unitsPerMm);
    const float pixdim[8] = {1.0f, step, step, step, 0, 0, 0, 0};
    put(bytes, 76, pixdim, sizeof pixdim);
    const float voxOffset = 352.0f;
    put(bytes, 108, &voxOffset, 4);
    bytes[123] = char(units);
    const std::int16_t codes[2] = {std::int16_t(sform ? 0 : 1), std::int16_t(sform ? 1 : 0)};  // qform, sform
    put(bytes, 252, codes, sizeof codes);
    const Vec3d o = origin * unitsPerMm;
    if (sform) {
        const float rows[12] = {step, 0, 0, float(o.x()), 0, step, 0, float(o.y()), 0, 0, step, float(o.z())};
        put(bytes, 280, rows, sizeof rows);
    } else {
        const float offsets[3] = {float(o.x()), float(o.y()), float(o.z())};  // quatern_b, c, d stay 0
        put(bytes, 268, offsets, sizeof offsets);
    }
    put(bytes, 344, "n+1", 4);
    const std::vector<std::int16_t> data = samples([&](int i, int j, int k) { return rasLattice(origin, i, j, k); });
    bytes.append(reinterpret_cast<const char*>(data.data()), data.size() * 2);
    std::ofstream(path, std::ios::binary) << bytes;
}

/// A NRRD with its samples attached, in `space` along `directions` from `origin` (that space's).
void writeNrrd(const std::filesystem::path& path, const std::string& space, const std::string& directions,
               const Vec3d& origin, const std::function<Vec3d(int, int, int)>& lpsOf)
{
    std::ofstream out(path, std::ios::binary);
    out << "NRRD0004\ntype: short\ndimension: 3\nspace: " << space << "\nsizes: " << kNx << " " << kNy << " " << kNz
        << "\nspace directions: " << directions << "\nspace origin: (" << origin.x() << "," << origin.y() << ","
        << origin.z() << ")\nencoding: raw\nendian: little\n\n";
    const std::vector<std::int16_t> data = samples(lpsOf);
    out.write(reinterpret_cast<const char*>(data.data()), std::streamsize(data.size() * 2));
}

/// Imports `scan` at the marker's surface and expects the marker at kMarker within half a voxel.
void expectMarker(const ScanVolume& scan, const std::string& format)
{
    const auto [radius, centre] = test::sphereOf(scanToLevelSet(scan, 100.0, 1.0));
    EXPECT_NEAR(radius, kMarkerRadius, 0.5 * kSpacing) << format;
    EXPECT_LT((centre - kMarker).length(), 0.5 * kSpacing) << format << ": marker at " << centre;
}

TEST(ScanFrame, EveryFormatPutsTheMarkerAtTheSameLpsPoint)
{
    TempDir dir;
    writeNifti(dir / "sform.nii", kRasOrigin, true, 2, 1.0);
    expectMarker(readScan(dir / "sform.nii"), "NIfTI sform (RAS)");
    writeNifti(dir / "qform.nii", kRasOrigin + Vec3d(4, -6, 2), false, 2, 1.0);
    expectMarker(readScan(dir / "qform.nii"), "NIfTI qform only (RAS)");

    writeNrrd(dir / "ras.nrrd", "right-anterior-superior", "(2,0,0) (0,2,0) (0,0,2)", kRasOrigin,
              [](int i, int j, int k) { return rasLattice(kRasOrigin, i, j, k); });
    expectMarker(readScan(dir / "ras.nrrd"), "NRRD right-anterior-superior");
    // Slicer's way with the same lattice: LPS, along negative x and y.
    writeNrrd(dir / "lps.nrrd", "left-posterior-superior", "(-2,0,0) (0,-2,0) (0,0,2)", flipped(kRasOrigin),
              [](int i, int j, int k) { return rasLattice(kRasOrigin, i, j, k); });
    expectMarker(readScan(dir / "lps.nrrd"), "NRRD left-posterior-superior");
    ASSERT_TRUE(readScan(dir / "lps.nrrd").warnings().empty()) << "a declared space needs no assumption";

    {  // MetaImage: ITK's LPS, the lattice turned half about z by its TransformMatrix
        std::ofstream out(dir / "flipped.mha", std::ios::binary);
        const Vec3d o = flipped(kRasOrigin);
        out << "ObjectType = Image\nNDims = 3\nTransformMatrix = -1 0 0 0 -1 0 0 0 1\nOffset = " << o.x() << " "
            << o.y() << " " << o.z() << "\nElementSpacing = 2 2 2\nDimSize = " << kNx << " " << kNy << " " << kNz
            << "\nElementType = MET_SHORT\nElementDataFile = LOCAL\n";
        const std::vector<std::int16_t> data =
            samples([](int i, int j, int k) { return rasLattice(kRasOrigin, i, j, k); });
        out.write(reinterpret_cast<const char*>(data.data()), std::streamsize(data.size() * 2));
    }
    expectMarker(readScan(dir / "flipped.mha"), "MetaImage");

    std::filesystem::create_directory(dir / "dicom");
    const Vec3d first(-9.0, -59.0, -13.0);  // LPS, as DICOM places its pixels
    const auto dicomLps = [&](int i, int j, int k) { return first + kSpacing * Vec3d(i, j, k); };
    const std::vector<std::int16_t> all = samples(dicomLps);
    for (int k = 0; k < kNz; ++k) {
        test::DicomSliceSpec slice;
        slice.rows = kNy, slice.columns = kNx;
        slice.rowSpacing = slice.columnSpacing = slice.sliceThickness = kSpacing;
        slice.position = first + Vec3d(0, 0, kSpacing * k);
        slice.instanceNumber = k + 1;
        for (std::size_t s = 0; s < std::size_t(kNx * kNy); ++s)
            slice.pixels.push_back(std::uint16_t(all[std::size_t(k) * kNx * kNy + s]));
        test::writeDicomSlice(dir / "dicom" / ("slice" + std::to_string(k) + ".dcm"), slice);
    }
    expectMarker(readScan(dir / "dicom"), "DICOM series");
}

TEST(ScanFrame, AScanInMicrometresOrMetresComesInMillimetres)
{
    TempDir dir;
    writeNifti(dir / "micro.nii", kRasOrigin, true, 3, 1000.0);  // NIFTI_UNITS_MICRON
    expectMarker(readScan(dir / "micro.nii"), "NIfTI in micrometres");
    writeNifti(dir / "metre.nii", kRasOrigin, true, 1, 0.001);  // NIFTI_UNITS_METER
    expectMarker(readScan(dir / "metre.nii"), "NIfTI in metres");
    writeNrrd(dir / "micro.nrrd", "RAS", "(2000,0,0) (0,2000,0) (0,0,2000)", kRasOrigin * 1000.0,
              [](int i, int j, int k) { return rasLattice(kRasOrigin, i, j, k); });
    std::string text;
    {
        std::ifstream in(dir / "micro.nrrd", std::ios::binary);
        text.assign(std::istreambuf_iterator<char>(in), {});
    }
    text.insert(text.find("encoding:"), "space units: \"um\" \"um\" \"um\"\n");
    std::ofstream(dir / "micro.nrrd", std::ios::binary) << text;
    expectMarker(readScan(dir / "micro.nrrd"), "NRRD in micrometres");
}

TEST(ScanFrame, ASpaceOfNoAnatomyOrUnknownUnitsIsTakenAsLpsMillimetresAndSaysSo)
{
    TempDir dir;
    writeNrrd(dir / "scanner.nrrd", "scanner-xyz", "(-2,0,0) (0,-2,0) (0,0,2)", flipped(kRasOrigin),
              [](int i, int j, int k) { return rasLattice(kRasOrigin, i, j, k); });
    const ScanVolume scan = readScan(dir / "scanner.nrrd");
    expectMarker(scan, "NRRD scanner-xyz");
    ASSERT_EQ(scan.warnings().size(), 1u);
    EXPECT_NE(scan.warnings().front().find("taken as left-posterior-superior (LPS)"), std::string::npos)
        << scan.warnings().front();
    EXPECT_EQ(anatomicalSigns("right-anterior-superior-time"), kRasSigns);
    EXPECT_EQ(anatomicalSigns("LAS"), Vec3d(1, -1, 1));
    EXPECT_FALSE(anatomicalSigns("3D-right-handed"));
    EXPECT_EQ(millimetresPer("\xC2\xB5m"), 1e-3);
    EXPECT_FALSE(millimetresPer("furlong"));
}

}  // namespace
}  // namespace sculpt
