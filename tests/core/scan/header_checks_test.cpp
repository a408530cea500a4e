// SPDX-License-Identifier: Apache-2.0
// The classes of bad scan headers (core/scan/header_checks.h), each built from a good file: non-
// finite numbers in any field that places the samples, sizes and spacings beyond the limits,
// data file lists of absurd range, compressed samples that do not inflate to what is declared.

#include "core/base/errors.h"
#include "core/scan/scan_readers.h"
#include "core/scan/scan_to_level_set.h"
#include "tests/support/file_bytes.h"
#include "tests/support/synthetic_scan.h"
#include "tests/support/temp_dir.h"

#include <gtest/gtest.h>
#include <vtkNIFTIImageWriter.h>
#include <vtkNew.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <zlib.h>

namespace sculpt {
namespace {

namespace fs = std::filesystem;
using namespace test;  // TempDir, fileBytes, writeFileBytes

/// The InputError readScan throws for `path` within a few seconds (naming it), or a failure.
std::string refusal(const fs::path& path)
{
    const auto start = std::chrono::steady_clock::now();
    try {
        readScan(path);
        ADD_FAILURE() << path << " was read";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
        EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10)) << e.what();
        return e.what();
    }
    return "";
}

/// 16^3 16-bit samples of a ball (100 on its surface), spacing 1.
vtkSmartPointer<vtkImageData> ballImage()
{
    return test::sampledImage(openvdb::Coord(16), openvdb::Vec3d(1.0), openvdb::Vec3d(0.0),
                              [](const openvdb::Vec3d& p) { return (p - openvdb::Vec3d(7.5)).length() - 5.0; });
}

std::string ballSamples()
{
    vtkSmartPointer<vtkImageData> image = ballImage();
    return std::string(static_cast<const char*>(image->GetScalarPointer()), 16 * 16 * 16 * 2);
}

fs::path writeNifti(const TempDir& dir, const std::string& name)
{
    vtkNew<vtkNIFTIImageWriter> writer;
    writer->SetInputData(ballImage());
    writer->SetFileName((dir / name).c_str());
    writer->Write();
    return dir / name;
}

TEST(HeaderChecks, NiftiFieldsThatAreNotFiniteAreRefusedInEveryPlacingField)
{
    TempDir dir;
    const std::string good = fileBytes(writeNifti(dir, "ball.nii"));
    ASSERT_NO_THROW(readScan(dir / "ball.nii"));
    // pixdim[1..3], scl_slope, scl_inter, quatern_b/c/d, qoffset_x/y/z, srow_x/y/z.
    std::vector<std::size_t> offsets{80, 84, 88, 112, 116, 256, 260, 264, 268, 272, 276};
    for (std::size_t at = 280; at < 328; at += 4) offsets.push_back(at);
    for (const std::size_t at : offsets) {
        for (const float bad : {std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN()}) {
            std::string bytes = good;
            std::memcpy(bytes.data() + at, &bad, sizeof bad);
            const fs::path path = dir / ("field_" + std::to_string(at) + (std::isnan(bad) ? "_nan" : "_inf") + ".nii");
            writeFileBytes(path, bytes);
            SCOPED_TRACE(path.filename().string());
            EXPECT_NE(refusal(path).find("not a finite number"), std::string::npos);
        }
    }
}

TEST(HeaderChecks, NiftiSpacingsBelowTheLimitAndOffsetsBeyondTheModelAreRefused)
{
    TempDir dir;
    std::string bytes = fileBytes(writeNifti(dir, "ball.nii"));
    const float tiny = 1e-6f;
    std::memcpy(bytes.data() + 84, &tiny, sizeof tiny);
    writeFileBytes(dir / "tiny.nii", bytes);
    EXPECT_NE(refusal(dir / "tiny.nii").find("below the smallest"), std::string::npos);

    // Placed 10^9 away by its qform (qform_code 1, sform_code 0): read, but no model reaches there.
    bytes = fileBytes(dir / "ball.nii");
    const float far = 1e9f;
    const std::int16_t codes[2] = {1, 0};
    std::memcpy(bytes.data() + 252, codes, sizeof codes);
    std::memcpy(bytes.data() + 268, &far, sizeof far);
    writeFileBytes(dir / "far.nii", bytes);
    const ScanVolume scan = readScan(dir / "far.nii");
    try {
        scanToLevelSet(scan, 100.0, 1.0);
        ADD_FAILURE() << "far.nii was converted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("far.nii reaches 1e+09 voxels from the origin"), std::string::npos)
            << e.what();
    }
}

// Found by scripts/fuzz.sh: an sform spacing of 3e29 (an invalid sform_code) made the default
// voxel size 2e28 and the anti-aliasing Gaussian's sigma as large: VTK sized its kernel in an
// int and crashed. A kernel wider than the image is clamped to it.
TEST(HeaderChecks, AnAntiAliasingGaussianWiderThanTheImageIsClampedToIt)
{
    TempDir dir;
    std::string bytes = fileBytes(writeNifti(dir, "ball.nii"));
    const float rows[12] = {3e29f, 0.f, 0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 0.f, 1.f, 0.f};  // srow_x/y/z
    const std::int16_t codes[2] = {0, 1};  // qform_code 0, sform_code 1
    std::memcpy(bytes.data() + 252, codes, sizeof codes);
    std::memcpy(bytes.data() + 280, rows, sizeof rows);
    writeFileBytes(dir / "wide.nii", bytes);
    const ScanVolume scan = readScan(dir / "wide.nii");
    ASSERT_GT(scan.spacing(0), 1e29);
    const std::optional<ScanVolume> smoothed = scan.antiAliased(2e28);
    ASSERT_TRUE(smoothed);
    EXPECT_EQ(smoothed->dims(), scan.dims());
    const auto [lo, hi] = scan.range();
    const auto [smoothLo, smoothHi] = smoothed->range();
    EXPECT_GE(smoothLo, lo - 1e-3);  // a Gaussian stays within the samples' range
    EXPECT_LE(smoothHi, hi + 1e-3);
}

TEST(HeaderChecks, CompressedNiftiThatDoesNotInflateIsRefused)
{
    TempDir dir;
    std::string bytes = fileBytes(writeNifti(dir, "ball.nii.gz"));
    ASSERT_NO_THROW(readScan(dir / "ball.nii.gz"));
    for (std::size_t i = bytes.size() / 2; i < bytes.size() / 2 + 16; ++i) bytes[i] = char(~bytes[i]);
    writeFileBytes(dir / "damaged.nii.gz", bytes);
    refusal(dir / "damaged.nii.gz");
}

void writeMetaImage(const fs::path& path, const std::string& header, const std::string& samples)
{
    writeFileBytes(path,
                   "ObjectType = Image\n" + header + "ElementType = MET_SHORT\nElementDataFile = LOCAL\n" + samples);
}

TEST(HeaderChecks, MetaImageDimensionsSpacingsAndPlacementAreChecked)
{
    TempDir dir;
    const std::string samples = ballSamples();
    writeMetaImage(dir / "good.mha", "NDims = 3\nDimSize = 16 16 16\nElementSpacing = 1 1 1\nOffset = 0 0 0\n",
                   samples);
    ASSERT_NO_THROW(readScan(dir / "good.mha"));
    const std::vector<std::pair<std::string, std::string>> cases{
        {"ndims_huge", "NDims = 1000000000\nDimSize = 16 16 16\n"},
        {"ndims_none", "DimSize = 16 16 16\n"},
        {"ndims_mismatch", "NDims = 2\nDimSize = 16 16 16\n"},
        {"dimsize_huge", "NDims = 3\nDimSize = 100000000 100000000 100000000\n"},
        {"dimsize_nan", "NDims = 3\nDimSize = nan 16 16\n"},
        {"dimsize_negative", "NDims = 3\nDimSize = -16 16 16\n"},
        {"spacing_inf", "NDims = 3\nDimSize = 16 16 16\nElementSpacing = 1 inf 1\n"},
        {"spacing_tiny", "NDims = 3\nDimSize = 16 16 16\nElementSpacing = 1 1 1e-9\n"},
        {"offset_nan", "NDims = 3\nDimSize = 16 16 16\nOffset = 0 nan 0\n"},
        {"matrix_inf", "NDims = 3\nDimSize = 16 16 16\nTransformMatrix = 1 0 0 0 1 0 0 0 -inf\n"},
        {"channels_huge", "NDims = 3\nDimSize = 16 16 16\nElementNumberOfChannels = 100000\n"}};
    for (const auto& [name, header] : cases) {
        SCOPED_TRACE(name);
        writeMetaImage(dir / (name + ".mha"), header, samples);
        refusal(dir / (name + ".mha"));
    }
}

TEST(HeaderChecks, MetaImageCompressedSamplesMustInflateToTheDeclaredSize)
{
    TempDir dir;
    const std::string header = "NDims = 3\nDimSize = 16 16 16\nCompressedData = True\n";
    writeMetaImage(dir / "garbage.mha", header, std::string(3000, 'x'));
    EXPECT_NE(refusal(dir / "garbage.mha").find("do not inflate"), std::string::npos);
    // A good stream of too few samples.
    writeMetaImage(dir / "short.mha", "NDims = 3\nDimSize = 16 16 17\nCompressedData = True\n", "");
    refusal(dir / "short.mha");
}

TEST(HeaderChecks, DetachedNrrdSliceListsAreBoundedAndEveryFileMustExist)
{
    TempDir dir;
    const std::string samples = ballSamples();
    const std::size_t slice = 16 * 16 * 2;
    for (int k = 0; k < 16; ++k) {
        char name[32];
        std::snprintf(name, sizeof name, "slice%03d.raw", k);
        writeFileBytes(dir / name, samples.substr(std::size_t(k) * slice, slice));
    }
    const std::string head = "NRRD0004\ntype: short\ndimension: 3\nsizes: 16 16 16\nendian: little\nencoding: raw\n";
    writeFileBytes(dir / "absurd.nhdr", head + "data file: slice%03d.raw 0 1000000000 1\n");
    EXPECT_NE(refusal(dir / "absurd.nhdr").find("names 1e+09 files"), std::string::npos);
    writeFileBytes(dir / "missing.nhdr", head + "data file: slice%03d.raw 0 16 1\n");
    EXPECT_NE(refusal(dir / "missing.nhdr").find("slice016.raw does not exist"), std::string::npos);
    writeFileBytes(dir / "format.nhdr", head + "data file: slice%s.raw 0 15 1\n");
    EXPECT_NE(refusal(dir / "format.nhdr").find("one %d"), std::string::npos);
    writeFileBytes(dir / "zero_step.nhdr", head + "data file: slice%03d.raw 0 15 0\n");
    refusal(dir / "zero_step.nhdr");
    writeFileBytes(dir / "list.nhdr", head + "data file: LIST\nslice000.raw\nnot_there.raw\n");
    EXPECT_NE(refusal(dir / "list.nhdr").find("not_there.raw does not exist"), std::string::npos);
}

TEST(HeaderChecks, NrrdPlacementFieldsMustBeFinite)
{
    TempDir dir;
    const std::string samples = ballSamples();
    const std::string head = "NRRD0004\ntype: short\ndimension: 3\nsizes: 16 16 16\nendian: little\nencoding: raw\n";
    writeFileBytes(dir / "good.nrrd", head + "spacings: 1 1 1\n\n" + samples);
    ASSERT_NO_THROW(readScan(dir / "good.nrrd"));
    for (const std::string& field :
         {std::string("spacings: 1 nan 1"), std::string("spacings: 1 1 1e-9"),
          std::string("space: RAS\nspace directions: (1,0,0) (0,inf,0) (0,0,1)"),
          std::string("space: RAS\nspace origin: (0,nan,0)"), std::string("sizes: 16 16 inf")}) {
        SCOPED_TRACE(field);
        const fs::path path = dir / ("bad" + std::to_string(std::hash<std::string>()(field) % 10000) + ".nrrd");
        writeFileBytes(path, head + field + "\n\n" + samples);
        refusal(path);
    }
}

}  // namespace
}  // namespace sculpt

namespace sculpt {
namespace {

/// An INRIMAGE-4 file of int16 samples i + 10 j + 100 k, `cpu`'s byte order, header `extra`
/// lines added, gzipped if `gzip`; `keep` of its sample bytes (all: -1).
void writeInrimage(const fs::path& path, const std::string& cpu, bool gzip, const std::string& extra = "",
                   long keep = -1)
{
    std::string header = "#INRIMAGE-4#{\nXDIM=5\nYDIM=4\nZDIM=3\nVDIM=1\nTYPE=signed fixed\nPIXSIZE=16 bits\n"
                         "SCALE=2**0\nCPU=" +
                         cpu + "\nVX=0.5\nVY=0.25\nVZ=2\n" + extra;
    header.resize(256 - 4, '\n');
    header += "##}\n";
    std::string samples;
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 5; ++i) {
                const std::int16_t v = std::int16_t(i + 10 * j + 100 * k - 50);
                const char lo = char(v & 0xff), hi = char((v >> 8) & 0xff);
                samples += cpu == "sun" ? std::string{hi, lo} : std::string{lo, hi};
            }
    if (keep >= 0) samples.resize(std::size_t(keep));
    const std::string bytes = header + samples;
    if (!gzip) return writeFileBytes(path, bytes);
    gzFile out = gzopen(path.string().c_str(), "wb");
    gzwrite(out, bytes.data(), unsigned(bytes.size()));
    gzclose(out);
}

}  // namespace

// CGAL's format: samples in either byte order, plain or gzipped, placed by VX, VY, VZ.
TEST(Inrimage, SamplesInEitherByteOrderPlainOrGzipped)
{
    TempDir dir;
    writeInrimage(dir / "little.inr", "decm", false);
    writeInrimage(dir / "big.inr.gz", "sun", true);
    for (const char* name : {"little.inr", "big.inr.gz"}) {
        const ScanVolume scan = readScan(dir / name);
        EXPECT_EQ(scan.dims(), openvdb::Coord(5, 4, 3)) << name;
        EXPECT_DOUBLE_EQ(scan.spacing(0), 0.5);
        EXPECT_DOUBLE_EQ(scan.spacing(2), 2.0);
        std::vector<float> slice(20);
        scan.readSlice(2, slice.data());
        EXPECT_EQ(slice[3 + 5 * 2], 3 + 10 * 2 + 200 - 50) << name;
        EXPECT_EQ(scan.range(), std::make_pair(-50.0, 4.0 + 30.0 + 200.0 - 50.0)) << name;
    }
}

// Every field that sizes or types the samples is checked, and every declared sample must be there.
TEST(Inrimage, BadHeadersAndMissingSamplesAreRefusedInOneLine)
{
    TempDir dir;
    writeFileBytes(dir / "none.inr", std::string("#INRIMAGE-4#{\nXDIM=5\n") + std::string(600, '\n'));
    EXPECT_NE(refusal(dir / "none.inr").find("the header never ends"), std::string::npos);
    writeFileBytes(dir / "other.inr", std::string(512, 'x'));
    EXPECT_NE(refusal(dir / "other.inr").find("not an INRIMAGE-4 file"), std::string::npos);
    writeInrimage(dir / "vector.inr", "decm", false, "VDIM=3\n");
    EXPECT_NE(refusal(dir / "vector.inr").find("VDIM"), std::string::npos);
    writeInrimage(dir / "huge.inr", "decm", false, "XDIM=100000000\nYDIM=100000000\n");
    EXPECT_NE(refusal(dir / "huge.inr").find("XDIM"), std::string::npos);
    writeInrimage(dir / "nan.inr", "decm", false, "VX=nan\n");
    EXPECT_NE(refusal(dir / "nan.inr").find("VX"), std::string::npos);
    writeInrimage(dir / "cpu.inr", "vax", false);
    EXPECT_NE(refusal(dir / "cpu.inr").find("CPU"), std::string::npos);
    writeInrimage(dir / "short.inr.gz", "decm", true, "", 101);
    EXPECT_NE(refusal(dir / "short.inr.gz").find("truncated"), std::string::npos);
}

}  // namespace sculpt
