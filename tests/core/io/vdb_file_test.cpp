// Documents in .vdb files: exact round trips, foreign files, and damaged files refused cleanly.

#include "core/base/errors.h"
#include "core/field/grid_checksum.h"
#include "core/io/vdb_file.h"
#include "core/primitives/analytic_shapes.h"
#include "tests/support/temp_dir.h"

#include <gtest/gtest.h>
#include <openvdb/io/File.h>

#include <fstream>
#include <random>

namespace sculpt {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

std::string readBytes(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

void writeBytes(const fs::path& path, const std::string& bytes)
{
    std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

void expectInputErrorNaming(const fs::path& path)
{
    try {
        readFieldImage(path);
        FAIL() << "expected an InputError for " << path;
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
    }
}

/// Leaf by leaf, value by value: the same bits and the same active topology.
void expectIdenticalGrids(const openvdb::FloatGrid& a, const openvdb::FloatGrid& b)
{
    ASSERT_EQ(a.tree().leafCount(), b.tree().leafCount());
    ASSERT_EQ(a.activeVoxelCount(), b.activeVoxelCount());
    EXPECT_EQ(a.background(), b.background());
    auto accB = b.getConstAccessor();
    for (auto leaf = a.tree().cbeginLeaf(); leaf; ++leaf) {
        const auto* other = accB.probeConstLeaf(leaf->origin());
        ASSERT_NE(other, nullptr) << leaf->origin();
        ASSERT_EQ(leaf->getValueMask(), other->getValueMask()) << leaf->origin();
        for (openvdb::Index i = 0; i < leaf->SIZE; ++i) {
            ASSERT_EQ(std::memcmp(&leaf->getValue(i), &other->getValue(i), sizeof(float)), 0);
        }
    }
}

TEST(VdbFile, RoundTripIsBitIdentical)
{
    TempDir dir;
    FieldImage torus = makeTorus(12.0, 4.0, 0.5);
    torus.setUnits("cm");
    writeFieldImage(torus, dir / "torus.vdb");
    const FieldImage back = readFieldImage(dir / "torus.vdb");
    expectIdenticalGrids(torus.grid(), back.grid());
    EXPECT_EQ(gridChecksum(torus.grid()), gridChecksum(back.grid()));
    EXPECT_EQ(back.units(), "cm");
    EXPECT_DOUBLE_EQ(back.voxelSize(), 0.5);
    EXPECT_DOUBLE_EQ(back.halfWidthVoxels(), torus.halfWidthVoxels());
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"torus.vdb"});  // no temporary left
}

TEST(VdbFile, ChecksumSeesOneChangedValue)
{
    FieldImage sphere = makeSphere(8.0, 1.0);
    const auto before = gridChecksum(sphere.grid());
    auto acc = sphere.mutableGrid().getAccessor();
    const openvdb::Coord ijk(8, 0, 0);
    acc.setValue(ijk, std::nextafter(acc.getValue(ijk), 1.0f));
    EXPECT_NE(gridChecksum(sphere.grid()), before);
}

TEST(VdbFile, ReadsForeignLevelSetWithoutOurMetadata)
{
    TempDir dir;
    const FieldImage sphere = makeSphere(8.0, 1.0);
    auto grid = sphere.grid().deepCopy();
    grid->setName("houdini_sdf");
    openvdb::io::File((dir / "foreign.vdb").string()).write({grid});
    const FieldImage back = readFieldImage(dir / "foreign.vdb");
    EXPECT_EQ(back.units(), FieldImage::kDefaultUnits);
    expectIdenticalGrids(sphere.grid(), back.grid());
}

TEST(VdbFile, RefusesFileWithoutFloatLevelSet)
{
    TempDir dir;
    auto fog = openvdb::FloatGrid::create(0.0f);
    fog->setGridClass(openvdb::GRID_FOG_VOLUME);
    fog->tree().setValue(openvdb::Coord(1, 2, 3), 1.0f);
    openvdb::io::File((dir / "fog.vdb").string()).write({fog});
    expectInputErrorNaming(dir / "fog.vdb");
}

TEST(VdbFile, RefusesMissingNotVdbAndDirectory)
{
    TempDir dir;
    expectInputErrorNaming(dir / "missing.vdb");
    writeBytes(dir / "text.vdb", "this is not a vdb file\n");
    expectInputErrorNaming(dir / "text.vdb");
    writeBytes(dir / "empty.vdb", "");
    expectInputErrorNaming(dir / "empty.vdb");
    expectInputErrorNaming(dir.path());
}

TEST(VdbFile, RefusesEveryTruncation)
{
    TempDir dir;
    writeFieldImage(makeSphere(10.0, 0.5), dir / "whole.vdb");
    const std::string bytes = readBytes(dir / "whole.vdb");
    for (double fraction : {0.01, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99, 0.9999}) {
        SCOPED_TRACE(std::to_string(fraction) + " of " + std::to_string(bytes.size()) + " bytes");
        const fs::path cut = dir / "cut.vdb";
        writeBytes(cut, bytes.substr(0, size_t(double(bytes.size()) * fraction)));
        expectInputErrorNaming(cut);
    }
}

TEST(VdbFile, RefusesCorruptedBytes)
{
    TempDir dir;
    writeFieldImage(makeSphere(10.0, 0.5), dir / "whole.vdb");
    const std::string bytes = readBytes(dir / "whole.vdb");
    std::mt19937 random(20261122);
    for (int trial = 0; trial < 20; ++trial) {
        std::string damaged = bytes;
        // Damage the payload (after the header and descriptors) in a few places.
        for (int k = 0; k < 4; ++k) {
            const size_t at = 400 + random() % (damaged.size() - 400);
            damaged[at] = char(damaged[at] ^ (1 + random() % 255));
        }
        SCOPED_TRACE("trial " + std::to_string(trial));
        writeBytes(dir / "bad.vdb", damaged);
        expectInputErrorNaming(dir / "bad.vdb");
    }
}

TEST(VdbFile, RefusesNewerFormatVersion)
{
    TempDir dir;
    const FieldImage sphere = makeSphere(8.0, 1.0);
    openvdb::MetaMap meta;
    meta.insertMeta("sculpt.format_version", openvdb::Int32Metadata(kVdbFormatVersion + 1));
    openvdb::io::File((dir / "future.vdb").string()).write({sphere.gridPtr()}, meta);
    expectInputErrorNaming(dir / "future.vdb");
}

TEST(VdbFile, WriteToMissingDirectoryLeavesNothing)
{
    TempDir dir;
    EXPECT_THROW(writeFieldImage(makeSphere(8.0, 1.0), dir / "no" / "such.vdb"), InputError);
    EXPECT_TRUE(dir.entries().empty());
}

TEST(VdbFile, OverwriteReplacesWholeFile)
{
    TempDir dir;
    writeFieldImage(makeSphere(20.0, 0.5), dir / "doc.vdb");
    const FieldImage small = makeSphere(8.0, 1.0);
    writeFieldImage(small, dir / "doc.vdb");
    EXPECT_EQ(gridChecksum(readFieldImage(dir / "doc.vdb").grid()), gridChecksum(small.grid()));
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"doc.vdb"});
}

}  // namespace
}  // namespace sculpt
