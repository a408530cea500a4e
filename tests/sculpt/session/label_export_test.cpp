// SPDX-License-Identifier: Apache-2.0
// Segmentations out: a three-label NIfTI (written here byte by byte, with a qfac of -1 as FSL's
// atlases have) imported a piece per label and exported on its own lattice gives back the same
// header geometry and each label's samples (Dice >= 0.98); NRRD and Slicer's .seg.nrrd lie on the
// same lattice, and the .seg.nrrd keeps each piece's name and colour for our importer.

#include "core/base/errors.h"
#include "core/scan/label_map_files.h"
#include "core/scan/scan_readers.h"
#include "sculpt/session/label_export.h"
#include "sculpt/session/label_names.h"
#include "sculpt/session/shape_import.h"
#include "tests/support/temp_dir.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

namespace sculpt {
namespace {

using openvdb::Vec3d;

constexpr int kNx = 40, kNy = 36, kNz = 30;
constexpr double kSpacing[3] = {1.0, 1.25, 1.5};
// The RAS sform, rows for column vectors; its z column negative (qfac -1).
constexpr float kSrow[3][4] = {{1.0f, 0, 0, -20.0f}, {0, 1.25f, 0, -22.0f}, {0, 0, -1.5f, 40.0f}};

/// The label of sample (i, j, k) in file order: a ball (1), a box (2) and an ellipsoid (5), in
/// millimetres along the index axes.
std::int16_t labelAt(int i, int j, int k)
{
    const Vec3d p(i * kSpacing[0], j * kSpacing[1], k * kSpacing[2]);
    if ((p - Vec3d(12, 15, 15)).length() < 7.0) return 1;
    if (p.x() >= 24 && p.x() <= 34 && p.y() >= 6 && p.y() <= 22 && p.z() >= 5 && p.z() <= 20) return 2;
    const Vec3d e((p.x() - 20) / 8, (p.y() - 33) / 6, (p.z() - 30) / 7);
    return e.lengthSqr() < 1.0 ? 5 : 0;
}

template <typename T>
void put(std::string& bytes, std::size_t at, T value)
{
    std::memcpy(bytes.data() + at, &value, sizeof value);
}

template <typename T>
T get(const std::string& bytes, std::size_t at)
{
    T value;
    std::memcpy(&value, bytes.data() + at, sizeof value);
    return value;
}

/// The labels as a NIfTI-1 file of int16 samples, placed by kSrow and by the same qform.
std::vector<std::int16_t> writeLabelNifti(const std::filesystem::path& path)
{
    std::string bytes(352, '\0');
    put(bytes, 0, std::int32_t(348));
    const std::int16_t dim[8] = {3, kNx, kNy, kNz, 1, 1, 1, 1};
    std::memcpy(bytes.data() + 40, dim, sizeof dim);
    put(bytes, 70, std::int16_t(4));  // DT_INT16
    put(bytes, 72, std::int16_t(16));
    const float pixdim[8] = {-1.0f, float(kSpacing[0]), float(kSpacing[1]), float(kSpacing[2]), 0, 0, 0, 0};
    std::memcpy(bytes.data() + 76, pixdim, sizeof pixdim);
    put(bytes, 108, 352.0f);
    bytes[123] = 2;                    // millimetres
    put(bytes, 252, std::int16_t(1));  // qform_code
    put(bytes, 254, std::int16_t(1));  // sform_code
    const float qoffset[3] = {kSrow[0][3], kSrow[1][3], kSrow[2][3]};
    std::memcpy(bytes.data() + 268, qoffset, sizeof qoffset);
    std::memcpy(bytes.data() + 280, kSrow, sizeof kSrow);
    std::memcpy(bytes.data() + 344, "n+1", 4);
    std::vector<std::int16_t> labels;
    for (int k = 0; k < kNz; ++k)
        for (int j = 0; j < kNy; ++j)
            for (int i = 0; i < kNx; ++i) labels.push_back(labelAt(i, j, k));
    bytes.append(reinterpret_cast<const char*>(labels.data()), labels.size() * 2);
    std::ofstream(path, std::ios::binary) << bytes;
    return labels;
}

std::string fileBytes(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

/// Dice coefficient of `label` between two label arrays of one lattice.
template <typename A, typename B>
double dice(const std::vector<A>& a, const std::vector<B>& b, int label)
{
    std::size_t both = 0, inA = 0, inB = 0;
    for (std::size_t n = 0; n < a.size(); ++n) {
        inA += a[n] == label;
        inB += b[n] == label;
        both += a[n] == label && b[n] == label;
    }
    return 2.0 * double(both) / double(inA + inB);
}

/// Every sample of a scan, in its index order, as integers.
std::vector<int> samplesOf(const ScanVolume& scan)
{
    const openvdb::Coord d = scan.dims();
    std::vector<float> slice(std::size_t(d.x()) * std::size_t(d.y()));
    std::vector<int> out;
    for (int k = 0; k < d.z(); ++k) {
        scan.readSlice(k, slice.data());
        for (float v : slice) out.push_back(int(std::lround(v)));
    }
    return out;
}

void expectSameLattice(const ScanLattice& a, const ScanLattice& b, const std::string& format)
{
    EXPECT_EQ(a.dims, b.dims) << format;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(a.worldFromIndex[r][c], b.worldFromIndex[r][c], 1e-6) << format;
}

class LabelExport : public ::testing::Test {
protected:
    void SetUp() override
    {
        original = writeLabelNifti(dir / "labels.nii");
        ImportReport report;
        pieces = importLabelPieces(dir / "labels.nii", {}, report);
        ASSERT_EQ(pieces.size(), 3u);
        pieces[0].name = "liver";
        pieces[0].colour = openvdb::Vec3f(0.9f, 0.25f, 0.125f);
        lattice = labelLattice(dir / "labels.nii", nullptr, "doc.vdb");
    }
    test::TempDir dir;
    std::vector<std::int16_t> original;
    std::vector<Piece> pieces;
    ScanLattice lattice;
};

TEST_F(LabelExport, ANiftiRoundTripKeepsTheHeaderGeometryAndEachLabel)
{
    EXPECT_EQ(pieces[0].label, 1);
    EXPECT_EQ(pieces[1].label, 2);
    EXPECT_EQ(pieces[2].label, 5);
    const LabelMap map = exportLabels(pieces, lattice, dir / "out.nii");
    ASSERT_EQ(map.segments.size(), 3u);

    // The header, read as bytes: the same dimensions and sform (and a label map's intent).
    const std::string bytes = fileBytes(dir / "out.nii");
    ASSERT_GE(bytes.size(), 352u);
    EXPECT_EQ(get<std::int32_t>(bytes, 0), 348);
    for (int a = 0; a < 3; ++a) EXPECT_EQ(get<std::int16_t>(bytes, 42 + 2 * a), (std::array{kNx, kNy, kNz})[a]);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c)
            EXPECT_NEAR(get<float>(bytes, std::size_t(280 + 16 * r + 4 * c)), kSrow[r][c], 1e-6) << r << "," << c;
    EXPECT_EQ(get<std::int16_t>(bytes, 68), 1002);  // NIFTI_INTENT_LABEL
    ASSERT_EQ(get<std::int16_t>(bytes, 70), 2);     // uint8: every label fits
    ASSERT_EQ(bytes.size(), 352u + original.size());

    // The samples, in the file's order: each label's within Dice 0.98 of the original.
    const std::vector<std::uint8_t> written(bytes.begin() + 352, bytes.end());
    for (int label : {1, 2, 5}) EXPECT_GE(dice(original, written, label), 0.98) << "label " << label;
    // Our reader places it as the original.
    expectSameLattice(readScan(dir / "out.nii").lattice(), lattice, ".nii");
}

TEST_F(LabelExport, NrrdAndSlicerSegmentationsLieOnTheSameLatticeAndKeepNamesAndColours)
{
    for (const char* name : {"out.nii.gz", "out.nrrd", "out.seg.nrrd"}) {
        exportLabels(pieces, lattice, dir / name);
        const ScanVolume back = readScan(dir / name);
        expectSameLattice(back.lattice(), lattice, name);
        const std::vector<int> samples = samplesOf(back);
        for (int label : {1, 2, 5}) EXPECT_GE(dice(original, samples, label), 0.98) << name << " label " << label;
    }
    std::vector<std::string> warnings;
    const std::map<int, LabelLook> looks = readLabelLooks(dir / "out.seg.nrrd", warnings);
    ASSERT_EQ(looks.size(), 3u);
    for (std::size_t p = 0; p < pieces.size(); ++p) {
        const LabelLook& look = looks.at(pieces[p].label);
        EXPECT_EQ(look.name, pieces[p].name);
        ASSERT_TRUE(look.colour.has_value());
        for (int c = 0; c < 3; ++c) EXPECT_NEAR((*look.colour)[c], pieces[p].colour[c], 1e-5);
    }
    ImportReport report;
    const std::vector<Piece> again = importLabelPieces(dir / "out.seg.nrrd", {}, report);
    ASSERT_EQ(again.size(), 3u);
    EXPECT_EQ(again[0].name, "liver");
    EXPECT_EQ(again[2].label, 5);
}

TEST_F(LabelExport, ADocumentWithoutAScanOrAnUnknownFormatIsRefusedNamingTheFile)
{
    try {
        labelLattice({}, nullptr, "doc.vdb");
        FAIL() << "a lattice came from nowhere";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("doc.vdb: keeps no scan"), std::string::npos) << e.what();
    }
    try {
        exportLabels(pieces, lattice, dir / "out.png");
        FAIL() << "a label map was written as a PNG";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("out.png"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
}

TEST_F(LabelExport, OverlappingPiecesGiveASampleToTheOneItIsDeepestIn)
{
    // A copy of the ball moved 3 mm along x overlaps it: the samples nearer its centre go to it.
    Piece moved = pieces[0];
    moved.name = "moved";
    moved.label = 0;  // numbered by the export
    moved.placement.setTranslation(Vec3d(3.0, 0.0, 0.0));
    std::vector<Piece> both{pieces[0], moved};
    const LabelMap map = labelMapOf(both, lattice);
    EXPECT_EQ(map.segments[1].label, 2) << "the smallest value unused";
    ASSERT_GT(map.segments[0].samples, 0u);
    ASSERT_GT(map.segments[1].samples, 0u);
    // The ball's samples split about evenly: neither swallowed the other.
    const double ratio = double(map.segments[0].samples) / double(map.segments[1].samples);
    EXPECT_NEAR(ratio, 1.0, 0.15);
}

// At the scale the README's limits state: 2,000 labels of 2 x 2 x 2 samples, side by side (a
// speck each at the scan's spacing, kept), import as 2,000 pieces and come back sample for sample.
// Its time is in pieces_bench (BM_LabelImport), not asserted here.
TEST(LabelRoundTrip, TwoThousandLabelsOfEightSamplesComeBackSampleForSample)
{
    const test::TempDir dir;
    constexpr int kBlocks[3] = {13, 13, 12}, kLabels = 2000;
    LabelMap map;
    map.lattice.dims = openvdb::Coord(2 * kBlocks[0], 2 * kBlocks[1], 2 * kBlocks[2]);
    for (int k = 0; k < map.lattice.dims.z(); ++k)
        for (int j = 0; j < map.lattice.dims.y(); ++j)
            for (int i = 0; i < map.lattice.dims.x(); ++i) {
                const int block = i / 2 + kBlocks[0] * (j / 2 + kBlocks[1] * (k / 2));
                map.labels.push_back(std::uint16_t(block < kLabels ? block + 1 : 0));
            }
    writeLabelMap(map, dir / "labels.nii");

    ImportReport report;
    const std::vector<Piece> pieces = importLabelPieces(dir / "labels.nii", {}, report);
    ASSERT_EQ(pieces.size(), std::size_t(kLabels));
    EXPECT_EQ(report.warnings.size(), std::size_t(kLabels)) << "each label a speck, kept and said so";
    for (int l = 0; l < kLabels; ++l) ASSERT_EQ(pieces[l].label, l + 1);
    EXPECT_EQ(labelMapOf(pieces, map.lattice).labels, map.labels);
}

}  // namespace
}  // namespace sculpt
