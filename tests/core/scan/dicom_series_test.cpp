// SPDX-License-Identifier: Apache-2.0
// DICOM series (core/scan/dicom_series.h, dicom_file.h): slice order and placement, the jitter
// real scanners leave in slice positions, compressed transfer syntaxes, multi-frame files, and
// refusal of gaps and mixed series.

#include "core/base/errors.h"
#include "core/field/grid_checksum.h"
#include "core/scan/scan_readers.h"
#include "core/scan/scan_to_level_set.h"
#include "tests/support/dicom_writer.h"
#include "tests/support/file_bytes.h"
#include "tests/support/synthetic_scan.h"
#include "tests/support/temp_dir.h"

#include <sys/resource.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>

namespace sculpt {
namespace {

namespace fs = std::filesystem;
using test::DicomSliceSpec;
using test::SyntheticBall;

using WorldSample = std::function<double(const openvdb::Vec3d&)>;

/// Axial slices of the ball's lattice, slice k at depth k * spacing plus jitter[k] (patient
/// orientation: x along rows, y down columns), each pixel the sample at its world position.
std::vector<DicomSliceSpec> ballSlices(const SyntheticBall& ball, const WorldSample& sample,
                                       const std::vector<double>& jitter = {})
{
    std::vector<DicomSliceSpec> slices;
    for (int k = 0; k < ball.dims.z(); ++k) {
        DicomSliceSpec slice;
        slice.rows = ball.dims.y();
        slice.columns = ball.dims.x();
        slice.rowSpacing = ball.spacing.y();
        slice.columnSpacing = ball.spacing.x();
        slice.sliceThickness = ball.spacing.z();
        slice.position = ball.origin + openvdb::Vec3d(0, 0, k * ball.spacing.z() + (jitter.empty() ? 0.0 : jitter[k]));
        slice.instanceNumber = k + 1;
        slice.seriesUid = "1.2.3";
        for (int r = 0; r < slice.rows; ++r) {
            for (int c = 0; c < slice.columns; ++c)
                slice.pixels.push_back(std::uint16_t(std::lround(
                    sample(slice.position + openvdb::Vec3d(c * ball.spacing.x(), r * ball.spacing.y(), 0)))));
        }
        slices.push_back(std::move(slice));
    }
    return slices;
}

WorldSample ballSample(const SyntheticBall& ball)
{
    return [ball](const openvdb::Vec3d& p) { return test::rampSample(ball.distance(p)); };
}

/// One file per slice, named out of slice order: the reader must sort by position, not by name.
std::vector<fs::path> writeSeries(const fs::path& dir, const std::vector<DicomSliceSpec>& slices)
{
    fs::create_directories(dir);
    std::vector<fs::path> files;
    for (std::size_t k = 0; k < slices.size(); ++k) {
        files.push_back(dir / ("im" + std::to_string((k * 7) % slices.size() + 100) + ".dcm"));
        test::writeDicomSlice(files.back(), slices[k]);
    }
    return files;
}

/// Uniform jitter of up to `share` of the spacing, the same on every run.
std::vector<double> jitterOf(const SyntheticBall& ball, double share)
{
    std::mt19937 random(17);
    std::uniform_real_distribution<double> uniform(-share * ball.spacing.z(), share * ball.spacing.z());
    std::vector<double> jitter(std::size_t(ball.dims.z()));
    for (double& j : jitter) j = uniform(random);
    return jitter;
}

void expectSameScan(const ScanVolume& a, const ScanVolume& b, const std::string& what)
{
    ASSERT_EQ(a.dims(), b.dims()) << what;
    EXPECT_TRUE(a.worldFromIndex().eq(b.worldFromIndex(), 1e-9)) << what;
    const std::size_t perSlice = std::size_t(a.dims().x()) * std::size_t(a.dims().y());
    std::vector<float> sa(perSlice), sb(perSlice);
    for (int k = 0; k < a.dims().z(); ++k) {
        a.readSlice(k, sa.data());
        b.readSlice(k, sb.data());
        ASSERT_EQ(sa, sb) << what << ": slice " << k;
    }
}

/// A copy of `dir` (the slices of one series) with one slice's bytes replaced.
fs::path seriesWithSlice(const fs::path& dir, const fs::path& into, const std::string& name, const std::string& bytes)
{
    fs::copy(dir, into, fs::copy_options::recursive);
    test::writeFileBytes(into / name, bytes);
    return into;
}

std::string messageOf(const std::function<void()>& read)
{
    try {
        read();
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(DicomSeries, KeepsSliceOrderSpacingAndPosition)
{
    test::TempDir dir;
    SyntheticBall ball;
    ball.centre = ball.origin + openvdb::Vec3d(19.5, 15.0, 26.0);  // off-centre in y and z
    writeSeries(dir.path(), ballSlices(ball, ballSample(ball)));
    const ScanVolume series = readScan(dir.path());
    EXPECT_EQ(series.dims(), ball.dims);
    EXPECT_TRUE(series.warnings().empty());
    test::expectBallAt(series, ball, "DICOM");
}

TEST(DicomSeries, JitteredSlicesAreEachPlacedAtTheirOwnPosition)
{
    const SyntheticBall ball;
    const std::vector<double> jitter = jitterOf(ball, 0.02);
    {
        test::TempDir dir;
        writeSeries(dir.path(), ballSlices(ball, ballSample(ball), jitter));
        const ScanVolume series = readScan(dir.path());
        ASSERT_EQ(series.warnings().size(), 1u);
        EXPECT_NE(series.warnings()[0].find("each is placed at its own position"), std::string::npos)
            << series.warnings()[0];
        test::expectBallAt(series, ball, "jittered DICOM");
    }
    // A ramp along the slice normal, steep enough (1000 per mm) that a slice assumed at its
    // nominal depth would be off by up to 40: resampled at even depths, every sample is the
    // ramp's value where the scan places it.
    test::TempDir dir;
    const auto ramp = [&](const openvdb::Vec3d& p) { return 1000.0 * (p.z() - ball.origin.z() + 1.0); };
    writeSeries(dir.path(), ballSlices(ball, ramp, jitter));
    const ScanVolume series = readScan(dir.path());
    const openvdb::Coord d = series.dims();
    std::vector<float> samples(std::size_t(d.x()) * std::size_t(d.y()));
    double worst = 0.0;
    for (int k = 0; k < d.z(); ++k) {
        series.readSlice(k, samples.data());
        for (int j = 0; j < d.y(); j += 7) {
            for (int i = 0; i < d.x(); i += 5) {
                const openvdb::Vec3d world = series.worldFromIndex().transform(openvdb::Vec3d(i, j, k));
                worst = std::max(worst, std::abs(samples[std::size_t(j * d.x() + i)] - ramp(world)));
            }
        }
    }
    EXPECT_LT(worst, 1.0) << "a slice is off its own position";
}

/// The series through `gdcmconv` with the given option, every file converted.
void convertSeries(const fs::path& from, const fs::path& to, const std::string& option)
{
    fs::create_directories(to);
    for (const auto& entry : fs::directory_iterator(from)) {
        const std::string command =
            "gdcmconv " + option + " '" + entry.path().string() + "' '" + (to / entry.path().filename()).string() + "'";
        ASSERT_EQ(std::system(command.c_str()), 0) << command << " (gdcmconv is in libgdcm-tools)";
    }
}

bool holds(const fs::path& file, const std::string& text)
{
    return test::fileBytes(file).find(text) != std::string::npos;
}

TEST(DicomSeries, CompressedSeriesGiveTheSameGrid)
{
    test::TempDir dir;
    const SyntheticBall ball;
    writeSeries(dir / "plain", ballSlices(ball, ballSample(ball)));
    const ScanVolume plain = readScan(dir / "plain");
    const std::uint64_t expected = gridChecksum(scanToLevelSet(plain, 100.0, 1.0).grid());
    struct Syntax {
        const char *option, *name, *uid;
    };
    for (const Syntax& s :
         {Syntax{"-J", "JPEG lossless", "1.2.840.10008.1.2.4.70"}, Syntax{"-R", "RLE", "1.2.840.10008.1.2.5"},
          Syntax{"-L", "JPEG-LS", "1.2.840.10008.1.2.4.80"}, Syntax{"-K", "JPEG 2000", "1.2.840.10008.1.2.4.90"}}) {
        const fs::path converted = dir / s.name;
        convertSeries(dir / "plain", converted, s.option);
        ASSERT_TRUE(holds(converted / "im100.dcm", s.uid)) << s.name << " was not written as " << s.uid;
        const ScanVolume scan = readScan(converted);
        expectSameScan(plain, scan, s.name);
        EXPECT_EQ(gridChecksum(scanToLevelSet(scan, 100.0, 1.0).grid()), expected) << s.name;
        // A slice cut inside its compressed fragments is refused by the codec, naming it.
        const std::string bytes = test::fileBytes(converted / "im103.dcm");
        const fs::path cut = seriesWithSlice(converted, dir / (std::string(s.name) + " cut"), "im103.dcm",
                                             bytes.substr(0, bytes.size() * 9 / 10));
        EXPECT_NE(messageOf([&] { readScan(cut); }).find((cut / "im103.dcm").string()), std::string::npos) << s.name;
    }
}

TEST(DicomSeries, MultiFrameFileEqualsTheSeries)
{
    test::TempDir dir;
    const SyntheticBall ball;
    const std::vector<DicomSliceSpec> slices = ballSlices(ball, ballSample(ball));
    writeSeries(dir / "series", slices);
    std::vector<DicomSliceSpec> shuffled = slices;  // frames out of order: placed by position
    std::swap(shuffled[2], shuffled[9]);
    test::writeDicomMultiFrame(dir / "enhanced.dcm", shuffled);
    expectSameScan(readScan(dir / "series"), readScan(dir / "enhanced.dcm"), "multi-frame");
}

TEST(DicomSeries, MissingSliceIsRefusedEvenWhenJittered)
{
    test::TempDir dir;
    const SyntheticBall ball;
    const auto files = writeSeries(dir.path(), ballSlices(ball, ballSample(ball), jitterOf(ball, 0.02)));
    fs::remove(files[5]);  // a slice in the middle
    const std::string message = messageOf([&] { readScan(dir.path()); });
    EXPECT_NE(message.find("missing slices"), std::string::npos) << message;
    EXPECT_NE(message.find(dir.path().string()), std::string::npos) << message;
}

TEST(DicomSeries, SeveralSeriesInOneDirectoryAreNamedAndOneIsOpenedByItsSlice)
{
    test::TempDir dir;
    const SyntheticBall ball;
    const auto files = writeSeries(dir.path(), ballSlices(ball, ballSample(ball)));
    for (int k = 0; k < 3; ++k) {  // a second series (a scout, say) in the same directory
        DicomSliceSpec slice;
        slice.rows = slice.columns = 20;
        slice.position = ball.origin + openvdb::Vec3d(0, 0, 1 + 2 * k);
        slice.seriesUid = "1.2.4";
        slice.pixels.assign(400, 50);
        test::writeDicomSlice(dir / ("scout" + std::to_string(k) + ".dcm"), slice);
    }
    const std::string message = messageOf([&] { readScan(dir.path()); });
    EXPECT_NE(message.find("2 series in one directory: 1.2.3 (22 files), 1.2.4 (3 files)"), std::string::npos)
        << message;
    EXPECT_NE(message.find("open one slice file"), std::string::npos) << message;

    const ScanVolume chosen = readScan(files[3]);
    EXPECT_EQ(chosen.dims(), ball.dims);
    test::expectBallAt(chosen, ball, "the series of one slice");
}

TEST(DicomSeries, MixedSizesInOneSeriesAreRefused)
{
    test::TempDir dir;
    const SyntheticBall ball;
    std::vector<DicomSliceSpec> slices = ballSlices(ball, ballSample(ball));
    slices[4].rows = slices[4].columns = 20;
    slices[4].pixels.assign(400, 50);
    writeSeries(dir.path(), slices);
    const std::string message = messageOf([&] { readScan(dir.path()); });
    EXPECT_NE(message.find("mixed series"), std::string::npos) << message;
}

TEST(DicomSeries, FilesThatAreNotDicomImagesAreSkippedWithOneWarning)
{
    test::TempDir dir;
    const SyntheticBall ball;
    writeSeries(dir.path(), ballSlices(ball, ballSample(ball)));
    std::ofstream(dir / "README.txt") << "Images of patient X. Open them with the viewer on this disc.\n";
    std::ofstream(dir / "autorun.inf") << "[autorun]\nopen=viewer.exe\n";
    test::writeDicomdir(dir / "DICOMDIR", {});  // an index of nothing: the files themselves are read
    const ScanVolume series = readScan(dir.path());
    ASSERT_EQ(series.warnings().size(), 1u);
    EXPECT_NE(series.warnings()[0].find("skipped 3 files that are not a DICOM image (DICOMDIR, README.txt, "
                                        "autorun.inf)"),
              std::string::npos)
        << series.warnings()[0];
    test::expectBallAt(series, ball, "a series beside other files");
}

TEST(DicomSeries, ADiscsDicomdirNamesItsImagesInFoldersOfAnyCase)
{
    test::TempDir dir;
    const SyntheticBall ball;
    const std::vector<DicomSliceSpec> slices = ballSlices(ball, ballSample(ball));
    // As a disc mounted in lower case shows the upper-case names its DICOMDIR gives.
    fs::create_directories(dir / "disc" / "dicom" / "st000001");
    std::vector<std::string> listed;
    for (std::size_t k = 0; k < slices.size(); ++k) {
        const std::string name = "im" + std::to_string(100 + k);
        test::writeDicomSlice(dir / "disc" / "dicom" / "st000001" / name, slices[k]);  // no extension
        listed.push_back("DICOM\\ST000001\\IM" + std::to_string(100 + k));
    }
    test::writeDicomdir(dir / "disc" / "DICOMDIR", listed);
    std::ofstream(dir / "disc" / "README.txt") << "a viewer's notes\n";
    const ScanVolume series = readScan(dir / "disc");
    ASSERT_EQ(series.warnings().size(), 1u);
    EXPECT_NE(series.warnings()[0].find("read the 22 images its DICOMDIR lists"), std::string::npos)
        << series.warnings()[0];
    test::expectBallAt(series, ball, "a disc's DICOMDIR");
    // One of its files, named without an extension, opens its series.
    expectSameScan(series, readScan(dir / "disc" / "dicom" / "st000001" / "im103"), "one file of the disc");

    listed.push_back("DICOM\\ST000001\\IM999");
    test::writeDicomdir(dir / "disc" / "DICOMDIR", listed);
    const std::string message = messageOf([&] { readScan(dir / "disc"); });
    EXPECT_NE(message.find("IM999, which is not on the disc"), std::string::npos) << message;
}

TEST(DicomSeries, ASliceThatMakesGdcmAbortIsRefusedNamingItAndTheProgramLivesOn)
{
    test::TempDir dir;
    const fs::path shared = SCULPT_TESTS_DIR "/bad-inputs/dicom_gdcm_abort";
    fs::copy(shared, dir / "abort");
    const std::string message = messageOf([&] { readScan(dir / "abort"); });
    EXPECT_NE(message.find("slice_2.dcm: the DICOM reader failed on this file"), std::string::npos) << message;

    // The same class made here: each length in a good slice's meta group made absurd.
    const SyntheticBall ball;
    const auto files = writeSeries(dir / "good", ballSlices(ball, ballSample(ball)));
    const std::string good = test::fileBytes(files[3]);
    const std::size_t lengthAt = 128 + 4 + 6;  // (0002,0010) UI: tag, VR, then its 2-byte length
    for (const std::uint16_t length :
         {std::uint16_t(0xFFFF), std::uint16_t(0x8001), std::uint16_t(3), std::uint16_t(0)}) {
        std::string bytes = good;
        std::memcpy(bytes.data() + lengthAt, &length, sizeof length);
        const fs::path series = seriesWithSlice(dir / "good", dir / ("meta_" + std::to_string(length)),
                                                files[3].filename().string(), bytes);
        const std::string refused = messageOf([&] { readScan(series); });
        EXPECT_NE(refused.find(series.string()), std::string::npos) << refused;
    }
}

/// The largest resident size any child process of this test has reached (ctest runs each test
/// in a process of its own).
double childPeakBytes()
{
    rusage usage{};
    getrusage(RUSAGE_CHILDREN, &usage);
    return double(usage.ru_maxrss) * 1024.0;
}

TEST(DicomSeries, AnElementLengthPastTheEndOfItsFileIsRefusedWithinWhatTheFilesCanHold)
{
    // A fuzzed slice whose sequence item claims 3.7 GB: GDCM allocates what a length claims.
    const fs::path fuzzed = SCULPT_TESTS_DIR "/bad-inputs/dicom_element_length_3_7GB/slice.dcm";
    EXPECT_NE(messageOf([&] { readScan(fuzzed); }).find(fuzzed.string()), std::string::npos);

    // The same class made here: the pixel data of a good series' slice claiming 3.7 GB.
    test::TempDir dir;
    const SyntheticBall ball;
    const auto files = writeSeries(dir / "good", ballSlices(ball, ballSample(ball)));
    std::string bytes = test::fileBytes(files[3]);
    const std::size_t pixelData = bytes.find(std::string("\xE0\x7F\x10\x00OW", 6));
    ASSERT_NE(pixelData, std::string::npos);
    const std::uint32_t length = 0xDDDDDDDD;
    std::memcpy(bytes.data() + pixelData + 8, &length, sizeof length);
    const fs::path series = seriesWithSlice(dir / "good", dir / "long", files[3].filename().string(), bytes);
    EXPECT_NE(messageOf([&] { readScan(series); }).find(series.string()), std::string::npos);

    // And a slice cut inside its pixel data: its length claims more than the file holds.
    const fs::path cut = seriesWithSlice(dir / "good", dir / "cut", files[3].filename().string(),
                                         test::fileBytes(files[3]).substr(0, pixelData + 12 + 100));
    EXPECT_NE(messageOf([&] { readScan(cut); }).find(cut.string()), std::string::npos);

    // The decoder's memory is bounded by the files' bytes (a few kB here), not the claims.
    EXPECT_LT(childPeakBytes(), 1.5 * double(1 << 30));
}

}  // namespace
}  // namespace sculpt
