// SPDX-License-Identifier: Apache-2.0
// End to end: the `sculpt` program on a temporary directory, as a user runs it.

#include "core/field/grid_checksum.h"
#include "core/io/mesh_import.h"
#include "core/io/ply_file.h"
#include "core/io/vdb_layout.h"
#include "core/primitives/analytic_shapes.h"
#include "tests/support/file_bytes.h"
#include "tests/support/mesh_checks.h"
#include "tests/support/run_sculpt.h"
#include "tests/support/temp_dir.h"
#include "tests/support/vdb_files.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <openvdb/io/File.h>

#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfVecAttribute.h>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace sculpt {
namespace {

using test::fileBytes;
using test::runSculpt;
using test::TempDir;
namespace fs = std::filesystem;
constexpr double kPi = 3.14159265358979323846;

nlohmann::json infoJson(const TempDir& dir, const std::string& file)
{
    const auto r = runSculpt("info --json " + file, dir.path());
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return nlohmann::json::parse(r.out);
}

// A bug report can say which build: the project's version and the commit it was built from.
TEST(SculptCli, VersionNamesTheBuildAndABareCallShowsTheUsage)
{
    TempDir dir;
    const auto r = runSculpt("--version", dir.path());
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out.rfind("sculpt " SCULPT_PROJECT_VERSION " (git ", 0), 0u) << r.out;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
    // A bare call shows how to call it (and fails, as a batch script must see).
    const auto bare = runSculpt("", dir.path());
    EXPECT_EQ(bare.exitCode, 2);
    EXPECT_NE(bare.err.find("Usage: sculpt [OPTIONS] SUBCOMMAND"), std::string::npos) << bare.err;
    EXPECT_NE(bare.err.find("export-labels"), std::string::npos) << bare.err;
}

// Each command's --help ends with examples of calling it.
TEST(SculptCli, EveryCommandsHelpShowsExamplesOfIt)
{
    TempDir dir;
    for (const std::string& command : test::sculptCommands()) {
        const auto r = runSculpt(command + " --help", dir.path());
        EXPECT_EQ(r.exitCode, 0) << command;
        const auto examples = r.out.find("Examples:\n  sculpt " + command + " ");
        EXPECT_NE(examples, std::string::npos) << command << ":\n" << r.out;
    }
}

TEST(SculptCli, NewInfoMeshOnTheDefaultClayBall)
{
    TempDir dir;
    auto r = runSculpt("new -o clay.vdb", dir.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("clay.vdb"), std::string::npos);

    const auto info = infoJson(dir, "clay.vdb");
    for (const char* key : {"voxel_size", "active_voxels", "memory_bytes", "bbox_min", "bbox_max", "volume", "area",
                            "euler_characteristic", "components"}) {
        EXPECT_TRUE(info.contains(key)) << key;
    }
    const double radius = info["bbox_max"][0].get<double>();
    EXPECT_NEAR(info["volume"].get<double>(), 4.0 / 3.0 * kPi * std::pow(radius, 3), 0.01 * std::pow(radius, 3) * 4.2);
    EXPECT_EQ(info["euler_characteristic"], 2);
    EXPECT_EQ(info["components"], 1);

    r = runSculpt("mesh clay.vdb -o clay.stl", dir.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto vtk = test::vtkMeshReport(dir / "clay.stl");
    EXPECT_EQ(vtk.boundaryEdges, 0);
    EXPECT_NEAR(vtk.volume, info["volume"].get<double>(), 0.01 * info["volume"].get<double>());
}

TEST(SculptCli, NewHonoursShapeAndSizes)
{
    TempDir dir;
    ASSERT_EQ(
        runSculpt("new --shape torus --radius 12 --minor-radius 3 --voxel-size 0.25 -o t.vdb", dir.path()).exitCode, 0);
    const auto torus = infoJson(dir, "t.vdb");
    EXPECT_EQ(torus["euler_characteristic"], 0);
    EXPECT_DOUBLE_EQ(torus["voxel_size"].get<double>(), 0.25);
    EXPECT_NEAR(torus["volume"].get<double>(), 2.0 * kPi * kPi * 12.0 * 9.0, 0.01 * 2132.0);
    EXPECT_NEAR(torus["bbox_max"][0].get<double>(), 15.0, 0.05);

    ASSERT_EQ(runSculpt("new --shape box --radius 4 --voxel-size 0.25 -o b.vdb", dir.path()).exitCode, 0);
    const auto box = infoJson(dir, "b.vdb");
    EXPECT_NEAR(box["volume"].get<double>(), 512.0, 5.12);
    EXPECT_EQ(box["euler_characteristic"], 2);
}

TEST(SculptCli, TextInfoNamesEveryMeasure)
{
    TempDir dir;
    ASSERT_EQ(runSculpt("new --radius 5 --voxel-size 0.5 -o s.vdb", dir.path()).exitCode, 0);
    const auto r = runSculpt("info s.vdb", dir.path());
    ASSERT_EQ(r.exitCode, 0);
    for (const char* label : {"voxel size", "active voxels", "memory", "bounding box", "volume", "area",
                              "euler characteristic", "components"}) {
        EXPECT_NE(r.out.find(label), std::string::npos) << label;
    }
}

TEST(SculptCli, DocumentsAreLpsAndMeshesNameTheirFrameWhichRasNegatesInXAndYOnly)
{
    TempDir dir;
    ASSERT_EQ(runSculpt("new --radius 5 --voxel-size 0.5 -o s.vdb", dir.path()).exitCode, 0);
    EXPECT_EQ(infoJson(dir, "s.vdb")["frame"], "LPS");
    EXPECT_EQ(infoJson(dir, "s.vdb")["frame_recorded"], true);
    EXPECT_NE(runSculpt("info s.vdb", dir.path()).out.find("frame:                LPS mm"), std::string::npos);
    // Another program's file (or ours from before frames were recorded) is read as LPS, and says so.
    test::writeNamedGrids(dir / "theirs.vdb", {{"surface", makeSphere(5.0, 0.5)}});
    EXPECT_EQ(infoJson(dir, "theirs.vdb")["frame_recorded"], false);
    EXPECT_NE(runSculpt("info theirs.vdb", dir.path()).out.find("assumed: the file records none"), std::string::npos);

    for (const char* ext : {".ply", ".obj", ".stl"}) {
        const std::string lps = std::string("lps") + ext, ras = std::string("ras") + ext;
        ASSERT_EQ(runSculpt("mesh s.vdb -o " + lps, dir.path()).exitCode, 0) << ext;
        ASSERT_EQ(runSculpt("mesh s.vdb --ras -o " + ras, dir.path()).exitCode, 0) << ext;
        EXPECT_NE(fileBytes(dir / lps).find("SPACE=LPS"), std::string::npos) << ext;
        EXPECT_NE(fileBytes(dir / ras).find("SPACE=RAS"), std::string::npos) << ext;
        // Our importer honours the header: both read back in LPS, the same.
        const TriangleMesh a = readMesh(dir / lps), b = readMesh(dir / ras);
        ASSERT_EQ(a.positions.size(), b.positions.size()) << ext;
        EXPECT_EQ(a.triangles, b.triangles) << ext;
        for (std::size_t v = 0; v < a.positions.size(); ++v)
            ASSERT_EQ(a.positions[v], b.positions[v]) << ext << " vertex " << v;
    }
    // As written: x and y negated, z and the triangles (their winding too) as they were.
    const TriangleMesh lps = readPly(dir / "lps.ply"), ras = readPly(dir / "ras.ply");
    ASSERT_EQ(lps.positions.size(), ras.positions.size());
    EXPECT_EQ(lps.triangles, ras.triangles);
    for (std::size_t v = 0; v < lps.positions.size(); ++v) {
        const auto& p = lps.positions[v];
        ASSERT_EQ(ras.positions[v], (std::array<float, 3>{-p[0], -p[1], p[2]})) << "vertex " << v;
    }
}

struct BadCall {
    const char* args;
    const char* mentions;  // the message must name what is wrong
};

void PrintTo(const BadCall& call, std::ostream* os) { *os << "sculpt " << call.args; }

class SculptCliBadInput : public ::testing::TestWithParam<BadCall> {};

TEST_P(SculptCliBadInput, ExitsTwoWithOneLineAndWritesNothing)
{
    TempDir dir;
    ASSERT_EQ(runSculpt("new --radius 5 --voxel-size 0.5 -o good.vdb", dir.path()).exitCode, 0);
    std::ofstream(dir / "corrupt.vdb") << "garbage that is not a vdb";
    std::ofstream(dir / "bad.json") << R"({"primitives": [{"name": "arm", "kernel": "metaball", "radius": -2,
        "skeleton": {"type": "point", "position": [0, 0, 0]}}]})";
    std::ofstream(dir / "broken.json") << R"({"primitives": [)";
    const std::string stroke = R"({"tool": "add", "radius": 1, "samples": [[5, 0, 0]]})";
    std::ofstream(dir / "s_ok.json") << R"({"events": [)" << stroke << "]}";
    std::ofstream(dir / "s_tool.json") << R"({"events": [)" << stroke
                                       << R"(, {"tool": "sponge", "radius": 1, "samples": [[5, 0, 0]]}]})";
    std::ofstream(dir / "s_field.json") << R"({"events": [{"tool": "add", "radius": 1}]})";
    std::ofstream(dir / "s_inf.json") << R"({"events": [{"tool": "add", "radius": 1, "samples": [[5, 0, -1e400]]}]})";
    std::ofstream(dir / "s_radius.json") << R"({"events": [{"tool": "carve", "radius": 0, "samples": [[5, 0, 0]]}]})";
    // A sample at 10^6, a path of a million stamps, and a spacing that piles stamps up.
    std::ofstream(dir / "s_far.json") << R"({"events": [{"tool": "add", "radius": 1, "samples": [[1e6, 0, 0]]}]})";
    std::ofstream(dir / "s_long.json")
        << R"({"events": [{"tool": "add", "radius": 1, "samples": [[5, 0, 0], [1e6, 0, 0]]}]})";
    std::ofstream(dir / "s_spacing.json")
        << R"({"events": [{"tool": "add", "radius": 1, "spacing": 0.0001, "samples": [[5, 0, 0]]}]})";
    std::ofstream(dir / "s_huge.json") << R"({"events": [)" << stroke
                                       << R"(, {"tool": "inflate", "radius": 90, "samples": [[5, 0, 0]]}]})";
    const auto blob = [](const std::string& operation, const std::string& radius, const std::string& at) {
        return R"({"iso": 0.5, "operation": ")" + operation +
               R"(", "primitives": [{"kernel": "soft-object", "radius": )" + radius +
               R"(, "skeleton": {"type": "point", "position": [)" + at + "]}}]}";
    };
    std::ofstream(dir / "huge_blob.json") << blob("union", "1e30", "0, 0, 0");
    std::ofstream(dir / "far_blob.json") << blob("union", "5", "1e15, 0, 0");
    std::ofstream(dir / "eat_all.json") << blob("difference", "40", "0, 0, 0");
    std::ofstream(dir / "junk.nii") << "not a NIfTI header, just some words";
    std::ofstream(dir / "tiny.raw") << "tiny";
    const auto before = dir.entries();
    const auto goodBytes = fileBytes(dir / "good.vdb");

    const auto r = runSculpt(GetParam().args, dir.path());
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find(GetParam().mentions), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(dir.entries(), before);
    EXPECT_EQ(fileBytes(dir / "good.vdb"), goodBytes);
}

INSTANTIATE_TEST_SUITE_P(
    Calls, SculptCliBadInput,
    ::testing::Values(
        BadCall{"info missing.vdb", "missing.vdb"}, BadCall{"info corrupt.vdb", "corrupt.vdb"},
        BadCall{"mesh corrupt.vdb -o out.ply", "corrupt.vdb"}, BadCall{"mesh good.vdb -o out.xyz", "out.xyz"},
        BadCall{"mesh good.vdb -o nodir/out.ply", "nodir"}, BadCall{"new --voxel-size 0 -o out.vdb", "voxel size"},
        BadCall{"new --voxel-size -1 -o out.vdb", "voxel size"},
        BadCall{"new --radius 1e5 --voxel-size 0.001 -o out.vdb", "memory"},
        BadCall{"new --shape cone -o out.vdb", "cone"}, BadCall{"new -o nodir/out.vdb", "nodir"},
        BadCall{"frobnicate", "frobnicate"}, BadCall{"smooth good.vdb --iterations -2 -o out.vdb", "iterations"},
        BadCall{"offset corrupt.vdb --distance 1 -o out.vdb", "corrupt.vdb"},
        BadCall{"morph good.vdb missing.vdb -o frames", "missing.vdb"},
        BadCall{"morph good.vdb good.vdb --frames 1 -o frames", "frames"},
        BadCall{"build bad.json -o out.vdb", "primitive 0 ('arm'): radius"},
        BadCall{"build broken.json -o out.vdb", "malformed JSON"},
        BadCall{"build missing.json -o out.vdb", "missing.json"},
        BadCall{"build bad.json --into corrupt.vdb -o out.vdb", "radius"},
        BadCall{"apply good.vdb s_tool.json -o out.vdb", "s_tool.json: events[1] ('sponge' stroke): unknown tool"},
        BadCall{"apply good.vdb s_field.json -o out.vdb", "events[0] ('add' stroke): missing field 'samples'"},
        BadCall{"apply good.vdb s_inf.json -o out.vdb", "malformed JSON at events[0].samples[0][2]"},
        BadCall{"apply good.vdb s_radius.json -o out.vdb",
                "events[0] ('carve' stroke): field 'radius' must be a positive"},
        BadCall{"apply good.vdb s_huge.json -o out.vdb",
                "events[1] ('inflate' stroke): field 'radius' (90) is larger than the model"},
        BadCall{"apply corrupt.vdb s_ok.json -o out.vdb", "corrupt.vdb"},
        BadCall{"apply good.vdb nothing.json -o out.vdb", "nothing.json"},
        BadCall{"apply good.vdb s_ok.json -o out.vdb --mesh out.xyz", "out.xyz"},
        BadCall{"import junk.nii -o out.vdb", "junk.nii"}, BadCall{"import nothing.nii -o out.vdb", "nothing.nii"},
        BadCall{"import good.vdb -o out.vdb", "good.vdb: keeps no scan"},
        BadCall{"import s_ok.json -o out.vdb", "unknown scan format '.json'"},
        BadCall{"import s_ok.json -o out.vdb", "raw samples need their layout given (--raw-dims"},
        BadCall{"export-labels good.vdb -o labels.nii", "good.vdb: keeps no scan to label"},
        BadCall{"export-labels good.vdb --like nothing.nii -o labels.nii", "nothing.nii"},
        BadCall{"export-labels good.vdb -o labels.png", "labels.png"},
        BadCall{"new --radius 0.4 --voxel-size 0.5 -o out.vdb", "choose a finer voxel size (a smaller --voxel-size)"},
        BadCall{"import tiny.raw --raw-dims 100000,100000,100000 -o out.vdb", "truncated"},
        BadCall{"import tiny.raw --raw-dims 2,2,1 --raw-type uint8 --iso 500 -o out.vdb", "outside the samples' range"},
        BadCall{"render missing.vdb -o out.png", "missing.vdb"},
        BadCall{"render corrupt.vdb -o out.exr", "corrupt.vdb"},
        BadCall{"render good.vdb -o out.png --width 0", "image size 0 x"},
        BadCall{"render good.vdb -o out.png --height 20000", "out of range (1 to 16384"},
        BadCall{"render good.vdb -o nodir/out.png", "nodir"}, BadCall{"render good.vdb -o out.tiff", "out.tiff"},
        BadCall{"render good.vdb -o out.png --background pink", "--background"},
        BadCall{"render good.vdb -o out.png --camera 0,0,0 --look-at 0,0,0", "coincide"},
        BadCall{"render good.vdb -o out.png --fov 200", "field of view"},
        BadCall{"render . -o frames --turntable 3", "not a directory of frames"},
        // Operations that would destroy the model, or reach beyond what a model can hold.
        BadCall{"offset good.vdb --distance -100 -o out.vdb", "good.vdb: offset -100 leaves nothing of the model"},
        BadCall{"smooth good.vdb --iterations 2000 -o out.vdb", "good.vdb: smooth 2000 leaves nothing of the model"},
        BadCall{"build eat_all.json --into good.vdb -o out.vdb", "combining the scene into good.vdb leaves nothing"},
        BadCall{"build huge_blob.json -o out.vdb", "primitive 0's influence reaches 2e+30 voxels from the origin"},
        BadCall{"build far_blob.json -o out.vdb", "beyond the largest model"},
        BadCall{"build huge_blob.json --voxel-size 0 -o out.vdb", "--voxel-size: must be a positive number (got 0)"},
        // Work without bound from absurd numbers: refused with the limit.
        BadCall{"apply good.vdb s_far.json -o out.vdb", "field 'samples[0].position' lies 999992 from the model"},
        BadCall{"apply good.vdb s_long.json -o out.vdb", "the stroke would make 3.99998e+06 stamps, more than 100000"},
        BadCall{"apply good.vdb s_spacing.json -o out.vdb", "field 'spacing' must be in [0.01, 4] radii"},
        BadCall{"smooth good.vdb --iterations 2000000000 -o out.vdb", "smoothing takes 1 to 10000 iterations"},
        BadCall{"offset good.vdb --distance 1e9 -o out.vdb", "an offset of 1e+09 is larger than the model"},
        BadCall{"import tiny.raw --raw-dims 2,2,1 --raw-type uint8 --voxel-size 1e30 -o out.vdb",
                "a voxel size of 1e+30 is larger than the scan"},
        BadCall{"import tiny.raw --raw-dims 2,2,1 --raw-type uint8 --smooth 1e9 -o out.vdb",
                "a smoothing sigma of 1e+09 is wider than the scan"},
        BadCall{"import tiny.raw --raw-dims 2,2,1 --raw-type uint8 --voxel-size inf -o out.vdb",
                "tiny.raw: the voxel size must be a positive number (got inf)"}),
    [](const auto& test) { return "case" + std::to_string(test.index); });

TEST(SculptCli, AnEditOfATwoGridFileUsesSurfaceAndKeepsTheOtherGridAndTheMetadata)
{
    TempDir dir;
    openvdb::MetaMap meta;
    meta.insertMeta("creator", openvdb::StringMetadata("Blender 4.2"));
    const FieldImage small = makeSphere(3.0, 0.5);
    test::writeNamedGrids(dir / "two.vdb", {{"collider", small}, {"surface", makeSphere(10.0, 0.5)}}, meta);
    const nlohmann::json info = infoJson(dir, "two.vdb");
    EXPECT_EQ(info["grid"], "surface");
    ASSERT_EQ(info["grids"].size(), 2u);
    EXPECT_EQ(info["grids"][0]["name"], "collider");
    EXPECT_EQ(info["grids"][0]["class"], "level set");
    EXPECT_NEAR(info["volume"].get<double>(), 4.0 / 3.0 * kPi * 1000.0, 0.02 * 4.0 / 3.0 * kPi * 1000.0);

    ASSERT_EQ(runSculpt("offset two.vdb --distance 1 -o out.vdb", dir.path()).exitCode, 0);
    EXPECT_NEAR(infoJson(dir, "out.vdb")["volume"].get<double>(), 4.0 / 3.0 * kPi * 1331.0,
                0.02 * 4.0 / 3.0 * kPi * 1331.0);
    openvdb::io::File out((dir / "out.vdb").string());
    out.open();
    EXPECT_EQ(out.getMetadata()->metaValue<std::string>("creator"), "Blender 4.2");
    const auto collider = openvdb::gridPtrCast<openvdb::FloatGrid>(out.readGrid("collider"));
    ASSERT_TRUE(collider);
    EXPECT_EQ(gridChecksum(*collider), gridChecksum(small.grid()));
}

TEST(SculptCli, SeveralLevelSetsAndNoSurfaceAskForGrid)
{
    TempDir dir;
    test::writeNamedGrids(dir / "pair.vdb", {{"left", makeSphere(4.0, 0.5)}, {"right", makeSphere(8.0, 0.5)}});
    const auto refused = runSculpt("info pair.vdb", dir.path());
    EXPECT_EQ(refused.exitCode, 2);
    EXPECT_NE(refused.err.find("pair.vdb: holds several level sets"), std::string::npos) << refused.err;
    EXPECT_NE(refused.err.find("'left' (level set), 'right' (level set)"), std::string::npos) << refused.err;
    EXPECT_NE(refused.err.find("with --grid NAME"), std::string::npos) << refused.err;
    ASSERT_EQ(runSculpt("smooth pair.vdb --grid right --iterations 2 -o out.vdb", dir.path()).exitCode, 0);
    // The document names the grid it edited: reading it again needs no choice.
    const nlohmann::json info = infoJson(dir, "out.vdb");
    EXPECT_EQ(info["grid"], "right");
    EXPECT_NEAR(info["volume"].get<double>(), 4.0 / 3.0 * kPi * 512.0, 0.03 * 4.0 / 3.0 * kPi * 512.0);
}

TEST(SculptCli, ImportedAndMorphedDocumentsNameTheirGridSurface)
{
    TempDir dir;
    ASSERT_EQ(runSculpt("new --radius 6 --voxel-size 0.5 -o a.vdb", dir.path()).exitCode, 0);
    ASSERT_EQ(runSculpt("mesh a.vdb -o a.stl", dir.path()).exitCode, 0);
    ASSERT_EQ(runSculpt("import a.stl --voxel-size 0.5 -o imported.vdb", dir.path()).exitCode, 0);
    ASSERT_EQ(runSculpt("new --shape box --radius 5 --voxel-size 0.5 -o b.vdb", dir.path()).exitCode, 0);
    ASSERT_EQ(runSculpt("morph imported.vdb b.vdb --frames 2 -o frames", dir.path()).exitCode, 0);
    for (const char* file : {"imported.vdb", "frames/frame_0000.vdb", "frames/frame_0001.vdb"}) {
        const VdbLayout layout = scanVdbLayout(dir / file);
        ASSERT_EQ(layout.grids.size(), 1u) << file;
        EXPECT_EQ(layout.grids[0].name, "surface") << file;
    }
}

// A mask (raw bytes, 0 and 1: a ball of radius 12 samples) imports anti-aliased by default,
// saying so, with the ball's area; --no-antialias keeps its voxel terraces (a tenth more area);
// --label 1 takes it as a label map.
// A scan's document keeps the scan: info says so, the document imports again at another
// iso-value as the scan itself does, and export-labels labels the kept lattice; --no-keep-scan
// keeps none.
TEST(SculptCli, AnImportedDocumentKeepsItsScanToImportAgainAndToLabel)
{
    TempDir dir;
    const int n = 32;
    std::string bytes(std::size_t(n * n * n), '\0');
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)  // 200 at the centre, falling 10 a voxel: a ball for every iso-value
                bytes[std::size_t((k * n + j) * n + i)] =
                    char(std::max(0.0, 200.0 - 10.0 * std::hypot(i - 15.6, j - 15.3, k - 15.8)));
    std::ofstream(dir / "ball.raw", std::ios::binary) << bytes;
    const std::string raw = "import ball.raw --raw-dims 32,32,32 --raw-type uint8 --raw-spacing 1,1,1.5 ";
    ASSERT_EQ(runSculpt(raw + "--iso 100 -o kept.vdb", dir.path()).exitCode, 0);
    ASSERT_EQ(runSculpt(raw + "--iso 60 -o direct.vdb", dir.path()).exitCode, 0);
    ASSERT_EQ(runSculpt(raw + "--iso 100 --no-keep-scan -o bare.vdb", dir.path()).exitCode, 0);
    const nlohmann::json kept = infoJson(dir, "kept.vdb")["kept_scan"];
    ASSERT_FALSE(kept.is_null());
    EXPECT_EQ(kept["dims"], nlohmann::json::array({32, 32, 32}));
    EXPECT_EQ(kept["source"], "ball.raw");
    EXPECT_EQ(kept["iso"], 100.0);
    EXPECT_GT(kept["memory_bytes"].get<double>(), 0.0);
    EXPECT_GT(kept["file_bytes"].get<double>(), 0.0);
    EXPECT_TRUE(infoJson(dir, "bare.vdb")["kept_scan"].is_null());
    EXPECT_NE(runSculpt("info kept.vdb", dir.path()).out.find("kept scan:            32 x 32 x 32 samples"),
              std::string::npos);

    // Imported again at iso 60 from the document alone: the surface the scan gives at 60.
    const auto again = runSculpt("import kept.vdb --iso 60 -o again.vdb", dir.path());
    ASSERT_EQ(again.exitCode, 0) << again.err;
    EXPECT_EQ(infoJson(dir, "again.vdb")["volume"], infoJson(dir, "direct.vdb")["volume"]);
    EXPECT_FALSE(infoJson(dir, "again.vdb")["kept_scan"].is_null()) << "the scan stays kept";

    // Labelled on the kept lattice: 32^3 samples, the ball's about its volume over a sample's.
    const auto labels = runSculpt("export-labels kept.vdb -o labels.nrrd", dir.path());
    ASSERT_EQ(labels.exitCode, 0) << labels.err;
    EXPECT_NE(labels.out.find("1 labels on 32 x 32 x 32 samples"), std::string::npos) << labels.out;
    EXPECT_NE(fileBytes(dir / "labels.nrrd").find("sizes: 32 32 32"), std::string::npos);
    const auto bare = runSculpt("export-labels bare.vdb -o bare.nrrd", dir.path());
    EXPECT_EQ(bare.exitCode, 2);
    EXPECT_NE(bare.err.find("bare.vdb: keeps no scan to label"), std::string::npos) << bare.err;
    EXPECT_EQ(runSculpt("export-labels bare.vdb --like kept.vdb -o bare.nrrd", dir.path()).exitCode, 0);
}

TEST(SculptCli, AMaskImportsAntiAliasedUnlessAskedNotTo)
{
    TempDir dir;
    const int n = 32;
    std::string bytes(std::size_t(n * n * n), '\0');
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                bytes[std::size_t((k * n + j) * n + i)] = std::hypot(i - 15.6, j - 15.3, k - 15.8) < 12.0 ? 1 : 0;
    std::ofstream(dir / "mask.raw", std::ios::binary) << bytes;
    const std::string import = "import mask.raw --raw-dims 32,32,32 --raw-type uint8 --iso 0.5 ";
    const auto smooth = runSculpt(import + "-o smooth.vdb", dir.path());
    ASSERT_EQ(smooth.exitCode, 0) << smooth.err;
    EXPECT_NE(smooth.out.find("two values only (a mask): its voxel terraces were anti-aliased"), std::string::npos)
        << smooth.out;
    ASSERT_EQ(runSculpt(import + "--no-antialias -o terraces.vdb", dir.path()).exitCode, 0);
    const double sphere = 4.0 * kPi * 144.0;
    EXPECT_NEAR(infoJson(dir, "smooth.vdb")["area"].get<double>(), sphere, 0.02 * sphere);
    EXPECT_GT(infoJson(dir, "terraces.vdb")["area"].get<double>(), 1.05 * sphere);
    // The same bytes as a label map: label 1's surface, anti-aliased as well.
    const auto label =
        runSculpt("import mask.raw --raw-dims 32,32,32 --raw-type uint8 --label 1 -o label.vdb", dir.path());
    ASSERT_EQ(label.exitCode, 0) << label.err;
    EXPECT_NE(label.out.find("label 1"), std::string::npos) << label.out;
    EXPECT_NEAR(infoJson(dir, "label.vdb")["area"].get<double>(), sphere, 0.02 * sphere);
}

// A label map (raw bytes: a box holding a ball, a ball touching it) imports as a document of a
// piece per label; info measures each and the total; mesh writes a closed file per piece with the
// piece's volume, one OBJ of an object each (that VTK reads whole), or the piece asked for;
// `pieces` renames, colours, hides, merges (the box and the ball filling it: the box's outer
// volume) and splits (the two balls merged into one piece: two solids).
TEST(SculptCli, ALabelMapImportsAsPiecesThatMeshAndChangeOneByOne)
{
    TempDir dir;
    const int nx = 48, ny = 32, nz = 32;
    std::string bytes;
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                const bool box = std::max({std::abs(i - 15.5), std::abs(j - 15.5), std::abs(k - 15.5)}) < 10.0;
                const double centre = std::hypot(i - 15.5, j - 15.5, k - 15.5);
                bytes.push_back(centre < 5.0 ? 2 : box ? 1 : std::hypot(i - 31.5, j - 15.5, k - 15.5) < 6.0 ? 3 : 0);
            }
    std::ofstream(dir / "map.raw", std::ios::binary) << bytes;
    const auto import = runSculpt("import map.raw --raw-dims 48,32,32 --labels -o pieces.vdb", dir.path());
    ASSERT_EQ(import.exitCode, 0) << import.err;
    EXPECT_NE(import.out.find("3 pieces"), std::string::npos) << import.out;
    const nlohmann::json info = infoJson(dir, "pieces.vdb");
    ASSERT_EQ(info["pieces"].size(), 3u);
    // The kept scan has its own line, not one among "other grids" (there are none).
    const std::string listing = runSculpt("info pieces.vdb", dir.path()).out;
    EXPECT_NE(listing.find("kept scan:"), std::string::npos) << listing;
    EXPECT_EQ(listing.find("other grids"), std::string::npos) << listing;
    double sum = 0.0;
    for (const auto& piece : info["pieces"]) sum += piece["volume"].get<double>();
    EXPECT_NEAR(info["volume"].get<double>(), sum, 1e-9 * sum);
    EXPECT_EQ(info["pieces"][1]["name"], "label 2");

    const auto ply = runSculpt("mesh pieces.vdb -o part.ply", dir.path());
    ASSERT_EQ(ply.exitCode, 0) << ply.err;
    for (int label = 1; label <= 3; ++label) {
        const test::VtkMeshReport mesh = test::vtkMeshReport(dir / ("part-label_" + std::to_string(label) + ".ply"));
        EXPECT_EQ(mesh.boundaryEdges + mesh.nonManifoldEdges, 0) << label;
        const double volume = info["pieces"][label - 1]["volume"].get<double>();
        EXPECT_NEAR(mesh.volume, volume, 0.01 * volume) << label;
    }
    ASSERT_EQ(runSculpt("mesh pieces.vdb -o all.obj", dir.path()).exitCode, 0);
    std::ifstream obj(dir / "all.obj");
    std::string line;
    std::vector<std::string> objects;
    while (std::getline(obj, line))
        if (line.rfind("o ", 0) == 0) objects.push_back(line.substr(2));
    EXPECT_EQ(objects, (std::vector<std::string>{"label 1", "label 2", "label 3"}));
    EXPECT_NEAR(test::vtkMeshReport(dir / "all.obj").volume, sum, 0.01 * sum);
    const auto one = runSculpt("mesh pieces.vdb --piece 'label 3' -o three.stl", dir.path());
    ASSERT_EQ(one.exitCode, 0) << one.err;
    const double three = info["pieces"][2]["volume"].get<double>();
    EXPECT_NEAR(test::vtkMeshReport(dir / "three.stl").volume, three, 0.01 * three);

    const auto edit = runSculpt("pieces pieces.vdb --rename 'label 3=ball' --colour 'ball=#ff8000' --hide ball "
                                "--merge 'label 1,label 2' -o edited.vdb",
                                dir.path());
    ASSERT_EQ(edit.exitCode, 0) << edit.err;
    const nlohmann::json edited = infoJson(dir, "edited.vdb");
    ASSERT_EQ(edited["pieces"].size(), 2u);
    EXPECT_EQ(edited["pieces"][0]["name"], "label 1");
    EXPECT_EQ(edited["pieces"][0]["components"], 1);  // the cavity filled
    const double box = 20.0 * 20.0 * 20.0;
    EXPECT_NEAR(edited["pieces"][0]["volume"].get<double>(), box, 0.01 * box);
    EXPECT_EQ(edited["pieces"][1]["name"], "ball");
    EXPECT_EQ(edited["pieces"][1]["visible"], false);
    EXPECT_NEAR(edited["pieces"][1]["colour"][1].get<double>(), 128.0 / 255.0, 1e-6);
    // The inner ball and the outer one, apart, merged into one piece and split again.
    ASSERT_EQ(
        runSculpt("pieces pieces.vdb --merge 'label 2,label 3' --split 'label 2' -o split.vdb", dir.path()).exitCode,
        0);
    const nlohmann::json split = infoJson(dir, "split.vdb");
    ASSERT_EQ(split["pieces"].size(), 3u);
    EXPECT_EQ(split["pieces"][1]["name"], "label 2 1");
    EXPECT_EQ(split["pieces"][2]["name"], "label 2 2");
    const auto unknown = runSculpt("pieces edited.vdb --delete nose -o x.vdb", dir.path());
    EXPECT_EQ(unknown.exitCode, 2);
    EXPECT_NE(unknown.err.find("no piece is named 'nose'"), std::string::npos) << unknown.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.vdb"));
}

/// A file of the regression corpus (tests/bad-inputs/) and the command that once failed on it.
struct Regression {
    std::string file;
    std::string command;  ///< FILE stands for the file's path; OUT for an output's name (else -o out.vdb)
};

void PrintTo(const Regression& r, std::ostream* os) { *os << "sculpt " << r.command << " on " << r.file; }

/// The corpus as its README's table lists it: rows "| `file` | `command` | it once |".
std::vector<Regression> regressionCorpus()
{
    std::ifstream readme(SCULPT_TESTS_DIR "/bad-inputs/README.md");
    std::vector<Regression> corpus;
    const std::regex row(R"(^\| `([^`]+)` \| `([^`]+)` \|)");
    std::smatch cells;
    for (std::string line; std::getline(readme, line);)
        if (std::regex_search(line, cells, row)) corpus.push_back({cells[1].str(), cells[2].str()});
    return corpus;
}

TEST(SculptCliRegressionCorpus, EveryFileInTheFolderIsInTheTable)
{
    std::set<std::string> listed;
    for (const Regression& r : regressionCorpus()) listed.insert(fs::path(r.file).begin()->string());
    EXPECT_GE(listed.size(), 20u);
    for (const auto& entry : fs::directory_iterator(SCULPT_TESTS_DIR "/bad-inputs")) {
        const std::string name = entry.path().filename().string();
        if (name != "README.md") {
            EXPECT_TRUE(listed.count(name)) << name << " is not in bad-inputs/README.md";
        }
    }
}

class SculptCliRegression : public ::testing::TestWithParam<Regression> {};

// Under 30 s and 2 GiB of address space (not only of memory used: the threads' stacks count).
TEST_P(SculptCliRegression, ExitsTwoWithOneLineInBoundedTimeAndMemoryAndWritesNothing)
{
    TempDir dir;
    const std::string corpus = SCULPT_TESTS_DIR "/bad-inputs/";
    ASSERT_EQ(runSculpt("new --radius 20 -o ball.vdb", dir.path()).exitCode, 0);  // what the strokes sculpt
    std::string args = GetParam().command;
    args.replace(args.find("FILE"), 4, "'" + corpus + GetParam().file + "'");
    if (const auto out = args.find("OUT"); out != std::string::npos) args.replace(out, 3, "out");
    else args += " -o out.vdb";
    const auto r = test::runSculptBounded(args, dir.path(), 30, 2048);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find(GetParam().file), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(TempDir::entriesOf(dir.path()), std::vector<std::string>{"ball.vdb"}) << "nothing written";
}

INSTANTIATE_TEST_SUITE_P(Corpus, SculptCliRegression, ::testing::ValuesIn(regressionCorpus()),
                         [](const auto& test) { return "case" + std::to_string(test.index); });

Imath::V3f exrCameraPosition(const std::filesystem::path& path)
{
    Imf::InputFile in(path.c_str());
    const auto* position = in.header().findTypedAttribute<Imf::V3fAttribute>("cameraPosition");
    return position ? position->value() : Imath::V3f(0.0f);
}

TEST(SculptCli, RenderWritesImagesTurntablesAndSequencesWithOneCamera)
{
    TempDir dir;
    ASSERT_EQ(runSculpt("new --radius 5 --voxel-size 0.5 -o ball.vdb", dir.path()).exitCode, 0);
    const std::string small = " --width 40 --height 30 --samples 1 --occlusion 2";
    auto r = runSculpt("render ball.vdb -o ball.png" + small, dir.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / "ball.png"));
    r = runSculpt("render ball.vdb -o ball.exr --background none" + small, dir.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;

    r = runSculpt("render ball.vdb --turntable 3 -o turn" + small, dir.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(TempDir::entriesOf(dir / "turn"),
              (std::vector<std::string>{"frame_0000.png", "frame_0001.png", "frame_0002.png"}));

    std::filesystem::create_directory(dir / "morph");
    ASSERT_EQ(runSculpt("new --radius 4 --voxel-size 0.5 -o morph/frame_0000.vdb", dir.path()).exitCode, 0);
    ASSERT_EQ(runSculpt("new --shape box --radius 6 --voxel-size 0.5 -o morph/frame_0001.vdb", dir.path()).exitCode, 0);
    r = runSculpt("render morph -o frames --format exr" + small, dir.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(TempDir::entriesOf(dir / "frames"), (std::vector<std::string>{"frame_0000.exr", "frame_0001.exr"}));
    const Imath::V3f first = exrCameraPosition(dir / "frames" / "frame_0000.exr");
    EXPECT_GT(first.length(), 6.0f);
    EXPECT_EQ(first, exrCameraPosition(dir / "frames" / "frame_0001.exr"));

    // Inside the ball: an image all the same, and one warning.
    r = runSculpt("render ball.vdb -o inside.png --camera 0,0,1" + small, dir.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("warning"), std::string::npos) << r.err;
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / "inside.png"));
}

TEST(SculptCli, SmoothAndOffsetChangeTheShape)
{
    TempDir dir;
    ASSERT_EQ(runSculpt("new --radius 10 --voxel-size 0.5 -o s.vdb", dir.path()).exitCode, 0);
    auto r = runSculpt("offset s.vdb --distance 2 -o grown.vdb", dir.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NEAR(infoJson(dir, "grown.vdb")["bbox_max"][0].get<double>(), 12.0, 0.05);

    r = runSculpt("smooth s.vdb --iterations 20 --keep-volume -o kept.vdb", dir.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const double v0 = infoJson(dir, "s.vdb")["volume"].get<double>();
    EXPECT_NEAR(infoJson(dir, "kept.vdb")["volume"].get<double>(), v0, 0.005 * v0);
    r = runSculpt("smooth s.vdb --iterations 20 -o shrunk.vdb", dir.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_LT(infoJson(dir, "shrunk.vdb")["volume"].get<double>(), 0.99 * v0);
}

TEST(SculptCli, MorphWritesFramesAndMeshes)
{
    TempDir dir;
    ASSERT_EQ(runSculpt("new --radius 6 --voxel-size 0.5 -o s.vdb", dir.path()).exitCode, 0);
    ASSERT_EQ(
        runSculpt("new --shape torus --radius 6 --minor-radius 2.5 --voxel-size 0.5 -o t.vdb", dir.path()).exitCode, 0);
    const auto r = runSculpt("morph s.vdb t.vdb --frames 3 -o frames --mesh stl", dir.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("converged"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("frame 0002 volume"), std::string::npos) << r.out;
    for (const char* name : {"frames/frame_0000.vdb", "frames/frame_0002.vdb", "frames/frame_0002.stl"}) {
        EXPECT_TRUE(std::filesystem::exists(dir / name)) << name;
    }
    EXPECT_EQ(infoJson(dir, "frames/frame_0002.vdb")["euler_characteristic"], 0);
    EXPECT_EQ(test::vtkMeshReport(dir / "frames/frame_0002.stl").boundaryEdges, 0);
}

// A morph, a turntable or a tracked export that fails after it began writing takes back what it
// wrote: the frames before the failure go, what was there before stays.
TEST(SculptCli, ACommandThatFailsMidWayLeavesNoPartialOutput)
{
    TempDir dir;
    ASSERT_EQ(runSculpt("new --radius 6 --voxel-size 0.5 -o s.vdb", dir.path()).exitCode, 0);
    ASSERT_EQ(
        runSculpt("new --shape torus --radius 6 --minor-radius 2.5 --voxel-size 0.5 -o t.vdb", dir.path()).exitCode, 0);
    // The third frame cannot be written (a directory stands where it goes).
    std::filesystem::create_directories(dir / "frames" / "frame_0002.vdb");
    auto r = runSculpt("morph s.vdb t.vdb --frames 4 -o frames --mesh ply --tracked tracked", dir.path());
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("frame_0002.vdb"), std::string::npos) << r.err;
    EXPECT_EQ(TempDir::entriesOf(dir / "frames"), std::vector<std::string>{"frame_0002.vdb"});
    EXPECT_FALSE(std::filesystem::exists(dir / "tracked")) << "made by the morph: taken back";

    std::filesystem::create_directories(dir / "turn" / "frame_0001.png");
    r = runSculpt("render s.vdb -o turn --turntable 3 --width 32 --height 24", dir.path());
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(TempDir::entriesOf(dir / "turn"), std::vector<std::string>{"frame_0001.png"});
}

TEST(SculptCli, MorphOfDisjointShapesAsksForAlign)
{
    TempDir dir;
    ASSERT_EQ(runSculpt("new --radius 3 --voxel-size 0.5 -o a.vdb", dir.path()).exitCode, 0);
    ASSERT_EQ(
        runSculpt("new --shape torus --radius 30 --minor-radius 3 --voxel-size 0.5 -o ring.vdb", dir.path()).exitCode,
        0);
    const auto r = runSculpt("morph a.vdb ring.vdb --frames 2 -o frames", dir.path());
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("do not overlap"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--align"), std::string::npos) << r.err;
}

TEST(SculptCli, AScenesVoxelSizeTooFineForItsExtentIsOneLineNamingTheScene)
{
    TempDir dir;
    std::string scene = fileBytes(SCULPT_DATA_DIR "/scenes/snowman.json");
    const auto at = scene.find("\"voxel_size\": 0.5");
    ASSERT_NE(at, std::string::npos);
    scene.replace(at, 18, "\"voxel_size\": 1e-6");
    test::writeFileBytes(dir / "fine.json", scene);
    const auto r = test::runSculptBounded("build fine.json -o out.vdb", dir.path(), 30, 4096);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(r.err.rfind("sculpt: fine.json", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.vdb"));
}

TEST(SculptCli, BuildBakesScenesAloneAndIntoADocument)
{
    TempDir dir;
    auto r = runSculpt("build '" SCULPT_DATA_DIR "/scenes/snowman.json' -o snow.vdb --mesh snow.ply", dir.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(infoJson(dir, "snow.vdb")["components"], 1);
    EXPECT_EQ(test::vtkMeshReport(dir / "snow.ply").boundaryEdges, 0);

    ASSERT_EQ(runSculpt("new --shape box --radius 20 -o box.vdb", dir.path()).exitCode, 0);
    r = runSculpt("build '" SCULPT_DATA_DIR "/scenes/carved_box.json' --into box.vdb -o carved.vdb", dir.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const double before = infoJson(dir, "box.vdb")["volume"].get<double>();
    const double after = infoJson(dir, "carved.vdb")["volume"].get<double>();
    EXPECT_LT(after, before - 200.0);  // a scoop of radius 8.3 off one corner: about 300 mm^3
    EXPECT_EQ(infoJson(dir, "carved.vdb")["euler_characteristic"], 2);
}

TEST(SculptCli, ApplyReplaysTheFaceScriptOnTheClayBall)
{
    TempDir dir;
    ASSERT_EQ(runSculpt("new -o clay.vdb", dir.path()).exitCode, 0);
    const std::string script = "'" SCULPT_DATA_DIR "/strokes/face.json'";
    auto r = runSculpt("apply clay.vdb " + script + " -o face.vdb --mesh face.ply", dir.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("2 undo, 1 redo"), std::string::npos) << r.out;
    const auto face = infoJson(dir, "face.vdb");
    const double clay = infoJson(dir, "clay.vdb")["volume"].get<double>();
    EXPECT_EQ(face["components"], 1) << "one shell: no bubbles where the eyeballs meet their sockets";
    EXPECT_EQ(face["euler_characteristic"], 2);
    EXPECT_GT(std::abs(face["volume"].get<double>() - clay), 100.0);  // sculpted, not the ball
    const auto vtk = test::vtkMeshReport(dir / "face.ply");
    EXPECT_EQ(vtk.boundaryEdges, 0);
    EXPECT_EQ(vtk.nonManifoldEdges, 0);
    EXPECT_NEAR(vtk.volume, face["volume"].get<double>(), 0.01 * face["volume"].get<double>());

    r = runSculpt("apply clay.vdb " + script + " -o again.vdb --threads 1", dir.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(infoJson(dir, "again.vdb"), face);
}

// The demo's face has sharp creases where a band estimate of volume and the mesh's differ; the
// volume control holds the mesh's, what `info`, the export and a printer see.
TEST(SculptCli, KeepVolumeSmoothingHoldsTheFacesMeshVolume)
{
    TempDir dir;
    ASSERT_EQ(runSculpt("new -o clay.vdb", dir.path()).exitCode, 0);
    auto r = runSculpt("apply clay.vdb '" SCULPT_DATA_DIR "/strokes/face.json' -o face.vdb", dir.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const double before = infoJson(dir, "face.vdb")["volume"].get<double>();
    for (const int iterations : {30, 200}) {
        const std::string out = "smoothed" + std::to_string(iterations) + ".vdb";
        r = runSculpt("smooth face.vdb --keep-volume --iterations " + std::to_string(iterations) + " -o " + out,
                      dir.path());
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_NEAR(infoJson(dir, out)["volume"].get<double>(), before, 0.001 * before) << iterations;
    }
}

TEST(SculptCli, ImportRemovesDebrisShellsAndSaysSo)
{
    // A cube of side 20 and, beside it, one under two voxels wide: too small to keep as a shell.
    TempDir dir;
    std::ofstream obj(dir / "two.obj");
    const auto cube = [&obj](double cx, double a) {
        for (int k = 0; k < 8; ++k)
            obj << "v " << cx + (k & 1 ? a : -a) << " " << (k & 2 ? a : -a) << " " << (k & 4 ? a : -a) << "\n";
    };
    cube(0.0, 10.0);
    cube(20.1, 0.45);
    for (int base : {0, 8}) {
        for (const char* face : {"1 3 4 2", "5 6 8 7", "1 2 6 5", "3 7 8 4", "1 5 7 3", "2 4 8 6"}) {
            obj << "f";
            std::istringstream corners(face);
            for (int c; corners >> c;) obj << " " << base + c;
            obj << "\n";
        }
    }
    obj.close();
    const auto r = runSculpt("import two.obj --voxel-size 0.5 -o two.vdb", dir.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("voxels of debris"), std::string::npos) << r.err;
    const auto info = runSculpt("info two.vdb --json", dir.path());
    EXPECT_NE(info.out.find("\"components\":1,"), std::string::npos) << info.out;
}

TEST(SculptCli, ImportMeshesAndScansAndMorphTowardsAMesh)
{
    TempDir dir;
    ASSERT_EQ(runSculpt("new --radius 5 --voxel-size 0.25 -o ball.vdb", dir.path()).exitCode, 0);
    ASSERT_EQ(runSculpt("mesh ball.vdb -o ball.stl", dir.path()).exitCode, 0);
    auto r = runSculpt("import ball.stl --voxel-size 0.25 -o back.vdb --mesh back.ply", dir.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const double original = infoJson(dir, "ball.vdb")["volume"].get<double>();
    EXPECT_NEAR(infoJson(dir, "back.vdb")["volume"].get<double>(), original, 0.01 * original);
    EXPECT_EQ(test::vtkMeshReport(dir / "back.ply").boundaryEdges, 0);

    ASSERT_EQ(runSculpt("new --shape box --radius 4 --voxel-size 0.25 -o box.vdb", dir.path()).exitCode, 0);
    r = runSculpt("morph box.vdb ball.stl --frames 2 -o frames", dir.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "frames/frame_0001.vdb"));

    const char* mri = "/usr/share/mricron/templates/ch2bet.nii.gz";
    if (!std::filesystem::exists(mri)) GTEST_SKIP() << mri << " missing: apt-get install mricron-data";
    r = runSculpt(std::string("import ") + mri + " --largest-component -o brain.vdb --mesh brain.stl", dir.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("(Otsu)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("cavities filled"), std::string::npos) << r.out;
    EXPECT_EQ(infoJson(dir, "brain.vdb")["components"], 1) << "one shell to print";
    const auto brain = test::vtkMeshReport(dir / "brain.stl");
    EXPECT_EQ(brain.boundaryEdges, 0);
    EXPECT_GT(brain.volume, 1.0e6);  // a human brain: well over a litre in mm^3
}

TEST(SculptCli, HelpExplainsEveryCommand)
{
    TempDir dir;
    for (const char* command : {"new", "info", "mesh", "smooth", "offset", "morph", "build", "apply", "import"}) {
        const auto r = runSculpt(std::string(command) + " --help", dir.path());
        EXPECT_EQ(r.exitCode, 0);
        EXPECT_NE(r.out.find("Usage"), std::string::npos) << command;
    }
    const auto r = runSculpt("new --help", dir.path());
    EXPECT_NE(r.out.find("--voxel-size FLOAT=0.5"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace sculpt
