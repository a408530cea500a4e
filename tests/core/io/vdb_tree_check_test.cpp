// SPDX-License-Identifier: Apache-2.0
// The walk of a float tree before OpenVDB reads it (core/io/vdb_tree_check.h): it ends where
// the file says for every coding OpenVDB writes, refuses the damage OpenVDB would leak or crash
// on, and finds the grids of streamed files, which carry no offsets.

#include "core/base/errors.h"
#include "core/field/csg_combine.h"
#include "core/field/grid_checksum.h"
#include "core/io/vdb_file.h"
#include "core/io/vdb_layout.h"
#include "core/io/vdb_tree_check.h"
#include "core/primitives/analytic_shapes.h"
#include "tests/support/file_bytes.h"
#include "tests/support/temp_dir.h"

#include <gtest/gtest.h>
#include <openvdb/io/File.h>
#include <openvdb/io/Stream.h>
#include <openvdb/tools/LevelSetSphere.h>

#include <cstring>
#include <fstream>
#include <random>

namespace sculpt {
namespace {

namespace fs = std::filesystem;
using test::fileBytes;
using test::TempDir;
using test::writeFileBytes;

/// The files here are written by OpenVDB itself, which honours their compression only once it
/// is initialised (the library's readers do that for the reads).
class VdbTreeCheck : public ::testing::Test {
protected:
    static void SetUpTestSuite() { openvdb::initialize(); }
};

/// Walks the file's first grid from its transform on; returns where the walk ended.
std::int64_t walkFirstGrid(const fs::path& path, bool throughBuffers)
{
    const VdbGridEntry grid = scanVdbLayout(path).grids.at(0);
    std::ifstream file(path, std::ios::binary);
    file.exceptions(std::ios::failbit | std::ios::badbit);
    file.seekg(grid.transformBegin);
    BoundedReader in(file, grid.end);
    checkVdbFloatTree(in, grid.coding, throughBuffers);
    return in.position();
}

/// The error readFieldImage gives; empty when the file reads.
std::string readError(const fs::path& path)
{
    try {
        readFieldImage(path);
        return {};
    } catch (const InputError& e) {
        return e.what();
    }
}

TEST_F(VdbTreeCheck, EndsWhereTheFileSaysForEveryCodingOpenVdbWrites)
{
    TempDir dir;
    std::vector<std::uint32_t> codings{openvdb::io::COMPRESS_NONE, openvdb::io::COMPRESS_ZIP,
                                       openvdb::io::COMPRESS_ACTIVE_MASK,
                                       openvdb::io::COMPRESS_ACTIVE_MASK | openvdb::io::COMPRESS_ZIP};
    if (openvdb::io::Archive::hasBloscCompression()) {
        codings.push_back(openvdb::io::COMPRESS_BLOSC);
        codings.push_back(openvdb::io::COMPRESS_ACTIVE_MASK | openvdb::io::COMPRESS_BLOSC);
    }
    const FieldImage torus = makeTorus(8.0, 3.0, 0.5);
    for (const std::uint32_t coding : codings) {
        for (const bool half : {false, true}) {
            SCOPED_TRACE("compression " + std::to_string(coding) + (half ? ", half floats" : ""));
            auto grid = torus.grid().deepCopy();
            grid->setGridClass(openvdb::GRID_UNKNOWN);  // OpenVDB never zips a level set's values
            grid->setSaveFloatAsHalf(half);
            const fs::path path = dir / "coded.vdb";
            openvdb::io::File file(path.string());
            file.setCompression(coding);
            file.write({grid});

            const VdbGridEntry entry = scanVdbLayout(path).grids.at(0);
            EXPECT_EQ(entry.coding.compression, coding);
            EXPECT_EQ(entry.coding.halfFloat, half);
            EXPECT_EQ(walkFirstGrid(path, false), entry.buffersBegin);
            EXPECT_EQ(walkFirstGrid(path, true), entry.end);
            EXPECT_NO_THROW(readVdbDocument(path));  // the walk lets every coding through
        }
    }
}

// Found by scripts/fuzz.sh: a leaf's Blosc chunk claiming 1.4 TB, which OpenVDB allocates
// before reading a byte of it. The walk checks the leaves' chunk lengths too.
TEST_F(VdbTreeCheck, ALeafChunkClaimingMoreThanTheFileHoldsIsRefusedBeforeOpenVdbAllocatesIt)
{
    const std::string error = readError(SCULPT_TESTS_DIR "/bad-inputs/vdb_blosc_huge_chunk.vdb");
    EXPECT_NE(error.find("a leaf's values run past the grid's end"), std::string::npos) << error;
}

// Found by scripts/fuzz.sh: a raw chunk whose length is -2^63, which has no signed negation
// (UndefinedBehaviorSanitizer stopped the walk there; this test runs in the sanitizer tree too).
TEST_F(VdbTreeCheck, ARawChunkOfTheMostNegativeLengthIsRefusedAsTheWrongSize)
{
    const std::string error = readError(SCULPT_TESTS_DIR "/bad-inputs/vdb_raw_chunk_int64_min.vdb");
    EXPECT_NE(error.find("tile values have the wrong size"), std::string::npos) << error;
}

TEST_F(VdbTreeCheck, DamagedTopologyIsRefusedOrReadWhole)
{
    TempDir dir;
    const FieldImage sphere = makeSphere(6.0, 1.0);
    writeFieldImage(sphere, dir / "whole.vdb");
    const VdbGridEntry grid = scanVdbLayout(dir / "whole.vdb").grids.at(0);
    const std::string bytes = fileBytes(dir / "whole.vdb");
    const fs::path bad = dir / "bad.vdb";
    std::mt19937 random(20261203);
    int refused = 0, read = 0;
    for (int trial = 0; trial < 300; ++trial) {
        std::string damaged = bytes;
        const auto at =
            std::size_t(grid.transformBegin + std::int64_t(random() % (grid.buffersBegin - grid.transformBegin)));
        damaged[at] = char(damaged[at] ^ (1 << (random() % 8)));
        writeFileBytes(bad, damaged);
        // Either refused naming the file, or read as OpenVDB reads it (no throw, no leak, no
        // crash: the sanitizer tree runs this test too).
        const std::string error = readError(bad);
        if (error.empty()) {
            ++read;
        } else {
            ++refused;
            EXPECT_NE(error.find(bad.string()), std::string::npos) << error;
        }
    }
    EXPECT_GT(refused, 0);
    EXPECT_GT(read, 0);  // flips in tile values or a transform's last bits are harmless
}

TEST_F(VdbTreeCheck, RefusesTwoTopLevelNodesAtOneOrigin)
{
    // Two spheres in two top-level nodes (4096 voxels wide): the second moved onto the first is
    // what OpenVDB's root reader leaks.
    auto grid = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(5.0f, {2048, 2048, 2048}, 1.0f);
    combineWhole(*grid, *openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(5.0f, {6144, 6144, 6144}, 1.0f),
                 CsgOperation::Union);
    grid->setName("surface");
    ASSERT_EQ(grid->tree().root().childCount(), 2u);
    TempDir dir;
    openvdb::io::File((dir / "two.vdb").string()).write({grid});
    ASSERT_EQ(readError(dir / "two.vdb"), "");

    std::string bytes = fileBytes(dir / "two.vdb");
    const std::int32_t second[3] = {4096, 4096, 4096};
    const std::string origin(reinterpret_cast<const char*>(second), sizeof second);
    const std::size_t at = bytes.find(origin, std::size_t(scanVdbLayout(dir / "two.vdb").grids.at(0).transformBegin));
    ASSERT_NE(at, std::string::npos);
    ASSERT_EQ(bytes.find(origin, at + 1), std::string::npos);  // the root's record, not a mask's bits
    std::memset(bytes.data() + at, 0, sizeof second);
    writeFileBytes(dir / "same.vdb", bytes);
    const std::string error = readError(dir / "same.vdb");
    EXPECT_NE(error.find("same.vdb"), std::string::npos) << error;
    EXPECT_NE(error.find("two top-level nodes"), std::string::npos) << error;
}

/// Writes the grids with OpenVDB's stream writer: no offsets, as pipes and some tools write.
void writeStreamed(const fs::path& path, const openvdb::GridPtrVec& grids)
{
    std::ofstream out(path, std::ios::binary);
    openvdb::io::Stream(out).write(grids);
}

openvdb::GridBase::Ptr namedSphere(const std::string& name, double radius)
{
    auto grid = makeSphere(radius, 1.0).grid().deepCopy();
    grid->setName(name);
    return grid;
}

openvdb::GridBase::Ptr vectorGrid()
{
    auto grid = openvdb::Vec3SGrid::create();
    grid->setName("velocity");
    grid->tree().setValue(openvdb::Coord(1, 2, 3), openvdb::Vec3s(1, 2, 3));
    return grid;
}

TEST_F(VdbTreeCheck, StreamedFilesAreWalkedGridByGrid)
{
    TempDir dir;
    const auto collider = namedSphere("collider", 3.0);
    const auto surface = namedSphere("surface", 6.0);

    writeStreamed(dir / "floats.vdb", {collider, surface});
    const VdbDocument both = readVdbDocument(dir / "floats.vdb");
    EXPECT_EQ(both.field.grid().getName(), "surface");
    EXPECT_EQ(gridChecksum(both.field.grid()), gridChecksum(*openvdb::gridPtrCast<openvdb::FloatGrid>(surface)));
    ASSERT_EQ(both.companions.grids.size(), 1u);
    EXPECT_TRUE(both.warnings.empty());

    // A vector grid cannot be walked: it is left out with a warning, and the file is kept.
    writeStreamed(dir / "then_vector.vdb", {surface, vectorGrid()});
    const VdbDocument first = readVdbDocument(dir / "then_vector.vdb");
    EXPECT_EQ(gridChecksum(first.field.grid()), gridChecksum(*openvdb::gridPtrCast<openvdb::FloatGrid>(surface)));
    ASSERT_EQ(first.warnings.size(), 1u);
    EXPECT_NE(first.warnings[0].find("'velocity'"), std::string::npos) << first.warnings[0];
    const std::string kept = fileBytes(dir / "then_vector.vdb");
    EXPECT_THROW(writeFieldImage(first.field, dir / "then_vector.vdb", first.companions), InputError);
    EXPECT_EQ(fileBytes(dir / "then_vector.vdb"), kept);

    // ...and nothing after it can be found.
    writeStreamed(dir / "vector_first.vdb", {vectorGrid(), surface});
    const std::string error = readError(dir / "vector_first.vdb");
    EXPECT_NE(error.find("vector_first.vdb"), std::string::npos) << error;
}

}  // namespace
}  // namespace sculpt
