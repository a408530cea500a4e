// SPDX-License-Identifier: Apache-2.0
// Documents in .vdb files: exact round trips, foreign files, and damaged files refused cleanly.

#include "core/base/errors.h"
#include "core/field/document_text.h"
#include "core/field/grid_checksum.h"
#include "core/io/vdb_file.h"
#include "core/io/vdb_layout.h"
#include "core/mesh/field_measures.h"
#include "core/primitives/analytic_shapes.h"
#include "tests/support/file_bytes.h"
#include "tests/support/temp_dir.h"
#include "tests/support/vdb_files.h"

#include <gtest/gtest.h>
#include <openvdb/io/File.h>

#include <cmath>
#include <functional>
#include <limits>
#include <random>

namespace sculpt {
namespace {

namespace fs = std::filesystem;
using test::fileBytes;
using test::TempDir;
using test::writeFileBytes;

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
    writeFileBytes(dir / "text.vdb", "this is not a vdb file\n");
    expectInputErrorNaming(dir / "text.vdb");
    writeFileBytes(dir / "empty.vdb", "");
    expectInputErrorNaming(dir / "empty.vdb");
    expectInputErrorNaming(dir.path());
}

TEST(VdbFile, RefusesEveryTruncation)
{
    TempDir dir;
    writeFieldImage(makeSphere(10.0, 0.5), dir / "whole.vdb");
    const std::string bytes = fileBytes(dir / "whole.vdb");
    for (double fraction : {0.01, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99, 0.9999}) {
        SCOPED_TRACE(std::to_string(fraction) + " of " + std::to_string(bytes.size()) + " bytes");
        const fs::path cut = dir / "cut.vdb";
        writeFileBytes(cut, bytes.substr(0, size_t(double(bytes.size()) * fraction)));
        expectInputErrorNaming(cut);
    }
}

TEST(VdbFile, RefusesCorruptedBytes)
{
    TempDir dir;
    writeFieldImage(makeSphere(10.0, 0.5), dir / "whole.vdb");
    const std::string bytes = fileBytes(dir / "whole.vdb");
    std::mt19937 random(20261122);
    for (int trial = 0; trial < 20; ++trial) {
        std::string damaged = bytes;
        // Damage the payload (after the header and descriptors) in a few places.
        for (int k = 0; k < 4; ++k) {
            const size_t at = 400 + random() % (damaged.size() - 400);
            damaged[at] = char(damaged[at] ^ (1 + random() % 255));
        }
        SCOPED_TRACE("trial " + std::to_string(trial));
        writeFileBytes(dir / "bad.vdb", damaged);
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

/// A small level set first, "surface" second, a fog volume third, and metadata of the file's own.
fs::path writeThreeGridFile(const TempDir& dir, const FieldImage& surface)
{
    auto small = makeSphere(3.0, 1.0).grid().deepCopy();
    small->setName("collider");
    auto named = surface.grid().deepCopy();
    named->setName("surface");
    auto fog = openvdb::FloatGrid::create(0.0f);
    fog->setName("density");
    fog->setGridClass(openvdb::GRID_FOG_VOLUME);
    fog->tree().setValue(openvdb::Coord(1, 2, 3), 0.5f);
    openvdb::MetaMap meta;
    meta.insertMeta("creator", openvdb::StringMetadata("Houdini 19.5"));
    const fs::path path = dir / "scene.vdb";
    openvdb::io::File(path.string()).write({small, named, fog}, meta);
    return path;
}

std::vector<std::string> gridNamesIn(const fs::path& path)
{
    std::vector<std::string> names;
    for (const VdbGridEntry& grid : scanVdbLayout(path).grids) names.push_back(grid.name);
    return names;
}

TEST(VdbFile, OpensTheGridNamedSurfaceAndKeepsTheOthersAndTheMetadata)
{
    TempDir dir;
    const FieldImage torus = makeTorus(10.0, 3.0, 0.5);
    const fs::path path = writeThreeGridFile(dir, torus);
    const VdbDocument document = readVdbDocument(path);
    EXPECT_EQ(gridChecksum(document.field.grid()), gridChecksum(torus.grid()));
    ASSERT_EQ(document.companions.grids.size(), 2u);
    EXPECT_TRUE(document.warnings.empty());

    writeFieldImage(document.field, dir / "saved.vdb", document.companions);
    EXPECT_EQ(gridNamesIn(dir / "saved.vdb"), (std::vector<std::string>{"surface", "collider", "density"}));
    openvdb::io::File saved((dir / "saved.vdb").string());
    saved.open();
    EXPECT_EQ(saved.getMetadata()->metaValue<std::string>("creator"), "Houdini 19.5");
    auto fog = openvdb::gridPtrCast<openvdb::FloatGrid>(saved.readGrid("density"));
    EXPECT_EQ(fog->tree().getValue(openvdb::Coord(1, 2, 3)), 0.5f);
    auto collider = openvdb::gridPtrCast<openvdb::FloatGrid>(saved.readGrid("collider"));
    EXPECT_EQ(gridChecksum(*collider), gridChecksum(makeSphere(3.0, 1.0).grid()));
    EXPECT_EQ(gridChecksum(readFieldImage(dir / "saved.vdb").grid()), gridChecksum(torus.grid()));
}

TEST(VdbFile, AsksForAGridWhenSeveralLevelSetsAndNoneIsSurface)
{
    TempDir dir;
    const FieldImage b = makeSphere(6.0, 1.0);
    const fs::path path = dir / "two.vdb";
    test::writeNamedGrids(path, {{"left", makeSphere(4.0, 1.0)}, {"right", b}});
    try {
        readFieldImage(path);
        FAIL() << "expected a request for a grid";
    } catch (const InputError& e) {
        EXPECT_EQ(e.remedy(), Remedy::ChooseGrid);
        const std::string what = e.what();
        for (const char* word : {"two.vdb", "'left'", "'right'", "choose one"})
            EXPECT_NE(what.find(word), std::string::npos) << what;
    }
    const VdbDocument right = readVdbDocument(path, "right");
    EXPECT_EQ(gridChecksum(right.field.grid()), gridChecksum(b.grid()));
    EXPECT_THROW(readFieldImage(path, "middle"), InputError);
    // What we write names the grid it edited: the next read needs no choice.
    writeFieldImage(right.field, dir / "edited.vdb", right.companions);
    EXPECT_EQ(readFieldImage(dir / "edited.vdb").grid().getName(), "right");
}

TEST(VdbFile, AGridOfATypeThisBuildCannotReadIsLeftOutWithAWarning)
{
    TempDir dir;
    auto points = openvdb::Vec3SGrid::create();
    points->setName("points");
    points->tree().setValue(openvdb::Coord(0, 0, 0), openvdb::Vec3s(1, 2, 3));
    auto surface = makeSphere(5.0, 1.0).grid().deepCopy();
    surface->setName("surface");
    const fs::path path = dir / "cache.vdb";
    openvdb::io::File(path.string()).write({points, surface});
    // Rename the vector grid's type to one no build registers, as a newer writer's would be.
    std::string bytes = fileBytes(path);
    const std::string type = openvdb::Vec3SGrid::gridType();
    const auto at = bytes.find(type);
    ASSERT_NE(at, std::string::npos);
    bytes.replace(at, type.size(), std::string(type.size(), 'Q'));
    writeFileBytes(path, bytes);

    const VdbDocument document = readVdbDocument(path);
    EXPECT_EQ(gridChecksum(document.field.grid()), gridChecksum(*surface));
    EXPECT_TRUE(document.companions.grids.empty());
    // Nothing we write may replace that file: the grid would be lost.
    EXPECT_THROW(writeFieldImage(document.field, path, document.companions), InputError);
    EXPECT_EQ(fileBytes(path), bytes);
    writeFieldImage(document.field, dir / "elsewhere.vdb", document.companions);
    ASSERT_EQ(document.warnings.size(), 1u);
    EXPECT_NE(document.warnings[0].find("'points'"), std::string::npos) << document.warnings[0];
}

TEST(VdbFile, ADensePhiIsRebuiltIntoABandWithAWarning)
{
    // Mantaflow's layout: every voxel of the domain active, background 0, distances in cells.
    const double h = 0.25, radius = 4.0;
    auto phi = openvdb::FloatGrid::create(0.0f);
    phi->setName("phi");
    phi->setTransform(openvdb::math::Transform::createLinearTransform(h));
    auto acc = phi->getAccessor();
    const int n = 24;
    for (int i = -n; i < n; ++i) {
        for (int j = -n; j < n; ++j) {
            for (int k = -n; k < n; ++k)
                acc.setValue({i, j, k}, float((std::sqrt(double(i * i + j * j + k * k)) * h - radius) / h));
        }
    }
    TempDir dir;
    const fs::path path = dir / "fluid.vdb";
    openvdb::io::File(path.string()).write({phi});
    EXPECT_THROW(readFieldImage(path), InputError);  // not a level set: only on request

    const VdbDocument document = readVdbDocument(path, "phi");
    ASSERT_EQ(document.warnings.size(), 1u);
    EXPECT_NE(document.warnings[0].find("rebuilt"), std::string::npos) << document.warnings[0];
    EXPECT_NEAR(document.field.halfWidthVoxels(), FieldImage::kDefaultHalfWidthVoxels, 1e-6);
    const FieldMeasures measures = measureField(document.field);
    EXPECT_NEAR(measures.volume, 4.0 / 3.0 * M_PI * std::pow(radius, 3), 0.02 * 4.0 / 3.0 * M_PI * std::pow(radius, 3));
    EXPECT_EQ(measures.eulerCharacteristic, 2);
}

TEST(VdbFile, DocumentsNameTheirGridSurface)
{
    TempDir dir;
    auto grid = makeSphere(5.0, 1.0).grid().deepCopy();
    grid->setName("");
    writeFieldImage(FieldImage(grid), dir / "unnamed.vdb");
    EXPECT_EQ(gridNamesIn(dir / "unnamed.vdb"), std::vector<std::string>{"surface"});
    EXPECT_EQ(grid->getName(), "");  // the field's own grid is untouched
}

TEST(VdbFile, RefusesLengthsBeyondTheFileBeforeAllocating)
{
    TempDir dir;
    writeFieldImage(makeSphere(5.0, 1.0), dir / "whole.vdb");
    std::string bytes = fileBytes(dir / "whole.vdb");
    // The first metadata name's length (after the 8+4+8+1+36-byte header and the 4-byte count).
    const std::size_t at = 8 + 4 + 8 + 1 + 36 + 4;
    const std::uint32_t huge = 0x7fffffff;
    std::memcpy(bytes.data() + at, &huge, sizeof huge);
    writeFileBytes(dir / "huge.vdb", bytes);
    try {
        readFieldImage(dir / "huge.vdb");
        FAIL() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("2147483647 bytes"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace sculpt

namespace sculpt {
namespace {

/// A placement: a turn about z, then 9 up.
openvdb::Mat4d turnedAndRaised()
{
    openvdb::Mat4d m = openvdb::math::rotation<openvdb::Mat4d>(openvdb::math::Z_AXIS, 0.3);
    m.postTranslate(openvdb::Vec3d(0.0, 0.0, 9.0));
    return m;
}

/// Three pieces, each with its own look (the second moved) and the third its own voxel size.
std::vector<Piece> threePieces()
{
    return {{{"head", {0.9f, 0.6f, 0.5f}, true}, makeSphere(6.0, 0.5)},
            {{"hat", {0.2f, 0.2f, 0.8f}, false, turnedAndRaised()}, makeBox(3.0, 0.5)},
            {{"eye", {1.0f, 1.0f, 1.0f}, true}, makeSphere(1.5, 0.25)}};
}

void expectSamePieces(const std::vector<Piece>& read, const std::vector<Piece>& written)
{
    ASSERT_EQ(read.size(), written.size());
    for (std::size_t i = 0; i < read.size(); ++i) {
        EXPECT_EQ(read[i].name, written[i].name);
        EXPECT_EQ(read[i].colour, written[i].colour) << read[i].name;
        EXPECT_EQ(read[i].visible, written[i].visible) << read[i].name;
        EXPECT_EQ(read[i].placement, written[i].placement) << read[i].name;
        EXPECT_EQ(gridChecksum(read[i].field.grid()), gridChecksum(written[i].field.grid())) << read[i].name;
        EXPECT_DOUBLE_EQ(read[i].field.voxelSize(), written[i].field.voxelSize()) << read[i].name;
    }
}

}  // namespace

// Pieces keep their names, colours, visibility, placements and voxels (each its own voxel size); a reader
// of one surface (the window today) opens the first and keeps the others, so saving it loses none.
TEST(VdbPieces, RoundTripWithTheirLooksAndSurviveAReaderOfOneSurface)
{
    TempDir dir;
    const std::vector<Piece> pieces = threePieces();
    writeVdbPieces(pieces, dir / "doc.vdb");
    EXPECT_EQ(gridNamesIn(dir / "doc.vdb"), (std::vector<std::string>{"head", "hat", "eye"}));
    const VdbPieces read = readVdbPieces(dir / "doc.vdb");
    expectSamePieces(read.pieces, pieces);
    EXPECT_TRUE(read.companions.grids.empty());
    EXPECT_TRUE(read.warnings.empty());

    VdbDocument document = readVdbDocument(dir / "doc.vdb");
    EXPECT_EQ(document.field.grid().getName(), "head");
    ASSERT_EQ(document.companions.grids.size(), 2u);
    writeFieldImage(document.field, dir / "saved.vdb", document.companions);
    expectSamePieces(readVdbPieces(dir / "saved.vdb").pieces, pieces);
    // One piece alone, by name, is checked against its own checksum.
    EXPECT_EQ(gridChecksum(readFieldImage(dir / "doc.vdb", "eye").grid()), gridChecksum(pieces[2].field.grid()));
}

// Every file of one surface is a document of one piece named after its grid, written back as it was.
TEST(VdbPieces, ADocumentOfOneSurfaceIsOnePieceAndSavesUnchanged)
{
    TempDir dir;
    const FieldImage torus = makeTorus(10.0, 3.0, 0.5);
    writeFieldImage(torus, dir / "one.vdb");
    const VdbPieces read = readVdbPieces(dir / "one.vdb");
    ASSERT_EQ(read.pieces.size(), 1u);
    EXPECT_EQ(read.pieces[0].name, "surface");
    writeVdbPieces(read.pieces, dir / "again.vdb");
    EXPECT_EQ(gridNamesIn(dir / "again.vdb"), std::vector<std::string>{"surface"});
    EXPECT_EQ(gridChecksum(readFieldImage(dir / "again.vdb").grid()), gridChecksum(torus.grid()));
    // Other programs' grids stay out of the pieces and are written back.
    const fs::path three = writeThreeGridFile(dir, torus);
    const VdbPieces mixed = readVdbPieces(three);
    ASSERT_EQ(mixed.pieces.size(), 1u);
    EXPECT_EQ(mixed.companions.grids.size(), 2u);
}

/// The message readVdbPieces refuses `path` with, or "" if it reads it.
std::string refusal(const fs::path& path)
{
    try {
        readVdbPieces(path);
    } catch (const InputError& e) {
        return e.what();
    }
    return {};
}

// What a document says of itself is checked on read whatever wrote it: a field changed after we
// sealed it is named as changed; in a file without the seal (another program's) each look is
// checked for what it may be.
TEST(VdbPieces, RefuseALookThatCannotBeAndValuesThatAreNotNumbers)
{
    TempDir dir;
    writeVdbPieces(threePieces(), dir / "doc.vdb");
    openvdb::Mat4d huge = openvdb::Mat4d::identity();
    huge.setToScale(openvdb::Vec3d(1e300));
    openvdb::Mat4d notANumber = openvdb::Mat4d::identity();
    notANumber(3, 0) = std::nan("");
    openvdb::Mat4d mirror = openvdb::Mat4d::identity();
    mirror(0, 0) = -1.0;
    const std::pair<const char*, openvdb::Mat4d> placements[] = {
        {"zeros", openvdb::Mat4d::zero()}, {"1e300", huge}, {"NaN", notANumber}, {"mirror", mirror}};
    for (const auto& [name, placement] : placements) {
        VdbDocument document = readVdbDocument(dir / "doc.vdb");
        document.companions.grids[0]->insertMeta("sculpt.piece_placement", openvdb::Mat4DMetadata(placement));
        const fs::path sealed = dir / (std::string("sealed-") + name + ".vdb");
        writeFieldImage(document.field, sealed, document.companions);
        EXPECT_NE(refusal(sealed).find(sealed.string() +
                                       ": piece 'hat': its field 'sculpt.piece_placement' was changed after it was "
                                       "written"),
                  std::string::npos)
            << name << ": " << refusal(sealed);
        document.companions.grids[0]->removeMeta("sculpt.sealed");
        const fs::path bad = dir / (std::string("placement-") + name + ".vdb");
        writeFieldImage(document.field, bad, document.companions);
        const std::string why = refusal(bad);
        EXPECT_NE(why.find(bad.string() + ": piece 'hat': its placement (sculpt.piece_placement)"), std::string::npos)
            << name << ": " << why;
    }
    VdbDocument document = readVdbDocument(dir / "doc.vdb");
    document.field.mutableGrid().insertMeta("sculpt.piece_colour",
                                            openvdb::Vec3SMetadata(openvdb::Vec3s(0.5f, NAN, 0.5f)));
    writeFieldImage(document.field, dir / "colour.vdb", document.companions);
    EXPECT_NE(refusal(dir / "colour.vdb").find("piece 'head': its colour"), std::string::npos)
        << refusal(dir / "colour.vdb");

    // A voxel that is not a number, in a file with a checksum (ours) and without (another program's).
    for (const float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
        FieldImage torus = makeTorus(10.0, 3.0, 0.5);
        torus.mutableGrid().tree().setValue(torus.grid().tree().cbeginLeaf()->origin(), bad);
        writeFieldImage(torus, dir / "ours.vdb");
        test::writeNamedGrids(dir / "theirs.vdb", {{"surface", torus}});
        for (const char* file : {"ours.vdb", "theirs.vdb"}) {
            const std::string why = refusal(dir / file);
            EXPECT_NE(why.find("holds a value that is not a finite number"), std::string::npos) << file << ": " << why;
            EXPECT_THROW(readFieldImage(dir / file), InputError) << file;
        }
    }
    // A piece whose background is not a number (every background tile is one): refused, naming the file.
    document = readVdbDocument(dir / "doc.vdb");
    auto hat = openvdb::gridPtrCast<openvdb::FloatGrid>(document.companions.grids[0]);
    hat->tree().root().setBackground(std::numeric_limits<float>::quiet_NaN(), /*updateChildNodes=*/true);
    hat->removeMeta("sculpt.sealed");
    hat->removeMeta("sculpt.checksum");
    writeFieldImage(document.field, dir / "background.vdb", document.companions);
    EXPECT_NE(refusal(dir / "background.vdb").find((dir / "background.vdb").string() + ": grid 'hat'"),
              std::string::npos)
        << refusal(dir / "background.vdb");
}

// Names and units are printed in listings and one-line messages: another program's grid named
// across two lines, or a unit a kilobyte long, is refused; our writer never writes one.
TEST(VdbPieces, NamesAndUnitsThatAreNotShortPrintableTextAreRefused)
{
    TempDir dir;
    VdbDocument document = [&] {
        writeVdbPieces(threePieces(), dir / "doc.vdb");
        return readVdbDocument(dir / "doc.vdb");
    }();
    document.companions.grids[0]->setName("hat\nrm -rf");
    writeFieldImage(document.field, dir / "newline.vdb", document.companions);
    const std::string newline = refusal(dir / "newline.vdb");
    EXPECT_NE(newline.find("a piece's name (its grid's name) cannot be: it holds a control character"),
              std::string::npos)
        << newline;
    EXPECT_EQ(newline.find('\n'), std::string::npos) << "one line";

    FieldImage ball = makeSphere(4.0, 0.5);
    ball.setUnits(std::string(1000, 'm'));
    writeFieldImage(ball, dir / "units.vdb");
    EXPECT_NE(refusal(dir / "units.vdb").find("its length unit (sculpt.units) cannot be: it is 1000 bytes long"),
              std::string::npos)
        << refusal(dir / "units.vdb");

    std::vector<Piece> tooLong = threePieces();
    tooLong[1].name = std::string(kMaxPieceNameBytes + 1, 'x');
    EXPECT_THROW(writeVdbPieces(tooLong, dir / "long.vdb"), InputError);
    EXPECT_FALSE(fs::exists(dir / "long.vdb"));
    EXPECT_EQ(printableText("left\thippocampus\n", 64), "left hippocampus ");
    EXPECT_EQ(printableText("caf\xc3\xa9", 4), "caf") << "cut at a whole character";
}

TEST(VdbPieces, RefuseAPieceWhoseVoxelsChangedAndNamesTakenTwice)
{
    TempDir dir;
    writeVdbPieces(threePieces(), dir / "doc.vdb");
    // A writer that changes a piece's voxels but keeps its recorded checksum: damage.
    VdbDocument document = readVdbDocument(dir / "doc.vdb");
    auto hat = openvdb::gridPtrCast<openvdb::FloatGrid>(document.companions.grids[0]);
    hat->tree().setValue(hat->tree().cbeginLeaf()->origin(), 0.125f);
    writeFieldImage(document.field, dir / "damaged.vdb", document.companions);
    try {
        readVdbPieces(dir / "damaged.vdb");
        FAIL() << "expected the damage to be seen";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("damaged.vdb"), std::string::npos) << what;
        EXPECT_NE(what.find("'hat'"), std::string::npos) << what;
    }
    std::vector<Piece> twice = threePieces();
    twice[2].name = "head";
    EXPECT_THROW(writeVdbPieces(twice, dir / "twice.vdb"), InputError);
    EXPECT_FALSE(fs::exists(dir / "twice.vdb"));
}

// The seal over what a document says of itself: a field of the file or of a piece changed, added
// or removed after we wrote it is refused and named; without seals (another program's file, or
// ours from before them) the document reads.
TEST(VdbPieces, TheSealNamesAFieldChangedAddedOrRemovedAfterWriting)
{
    TempDir dir;
    writeVdbPieces(threePieces(), dir / "doc.vdb");
    const auto tampered = [&](const std::string& name, const std::function<void(VdbDocument&)>& change) {
        VdbDocument document = readVdbDocument(dir / "doc.vdb");
        change(document);
        const fs::path path = dir / (name + ".vdb");
        writeFieldImage(document.field, path, document.companions);
        return refusal(path);
    };
    EXPECT_NE(tampered("colour",
                       [](VdbDocument& d) {
                           d.companions.grids[0]->insertMeta("sculpt.piece_colour",
                                                             openvdb::Vec3SMetadata(openvdb::Vec3s(0.1f, 0.2f, 0.3f)));
                       })
                  .find("piece 'hat': its field 'sculpt.piece_colour' was changed"),
              std::string::npos);
    EXPECT_NE(tampered("added",
                       [](VdbDocument& d) {
                           d.companions.grids[0]->insertMeta("sculpt.piece_label", openvdb::Int32Metadata(7));
                       })
                  .find("piece 'hat': its field 'sculpt.piece_label' was added"),
              std::string::npos);
    EXPECT_NE(tampered("removed", [](VdbDocument& d) { d.companions.grids[0]->removeMeta("sculpt.piece_visible"); })
                  .find("piece 'hat': its field 'sculpt.piece_visible' was removed"),
              std::string::npos);
    EXPECT_NE(tampered("garbled",
                       [](VdbDocument& d) {
                           d.companions.grids[0]->insertMeta("sculpt.sealed", openvdb::StringMetadata("garbage"));
                       })
                  .find("piece 'hat': its metadata seal is damaged"),
              std::string::npos);
    {  // The file's own fields, changed by another writer that kept everything else.
        openvdb::io::File file((dir / "doc.vdb").string());
        file.open();
        openvdb::GridPtrVecPtr grids = file.getGrids();
        openvdb::MetaMap::Ptr meta = file.getMetadata();
        file.close();
        meta->insertMeta("sculpt.units", openvdb::StringMetadata("in"));
        openvdb::io::File((dir / "inches.vdb").string()).write(*grids, *meta);
        EXPECT_NE(refusal(dir / "inches.vdb").find("its metadata: its field 'sculpt.units' was changed"),
                  std::string::npos)
            << refusal(dir / "inches.vdb");
    }
    // Without seals: read as another program's file, each field checked for what it may be.
    EXPECT_EQ(tampered("unsealed",
                       [](VdbDocument& d) {
                           for (const auto& grid : d.companions.grids) grid->removeMeta("sculpt.sealed");
                       }),
              "");
}

}  // namespace sculpt
