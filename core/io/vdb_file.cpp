// SPDX-License-Identifier: Apache-2.0
#include "core/io/vdb_file.h"

#include "core/base/atomic_file.h"
#include "core/base/errors.h"
#include "core/base/memory_budget.h"
#include "core/base/text_format.h"
#include "core/field/band_repair.h"
#include "core/field/document_text.h"
#include "core/field/grid_checksum.h"
#include "core/field/grid_tiles.h"
#include "core/field/placement_check.h"
#include "core/io/bounded_reader.h"
#include "core/io/content_uuid.h"
#include "core/io/memory_stream.h"
#include "core/io/metadata_seal.h"
#include "core/io/vdb_layout.h"
#include "core/io/vdb_tree_check.h"

#include <openvdb/io/File.h>
#include <openvdb/io/Stream.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>
#include <fstream>
#include <memory>
#include <set>

namespace sculpt {

namespace fs = std::filesystem;

namespace {

constexpr const char* kMetaVersion = "sculpt.format_version";
constexpr const char* kMetaUnits = "sculpt.units";
constexpr const char* kMetaVoxelSize = "sculpt.voxel_size";
constexpr const char* kMetaChecksum = "sculpt.checksum";
constexpr const char* kMetaPieceColour = "sculpt.piece_colour";
constexpr const char* kMetaPieceVisible = "sculpt.piece_visible";
constexpr const char* kMetaPiecePlacement = "sculpt.piece_placement";
constexpr const char* kMetaPieceLabel = "sculpt.piece_label";
constexpr const char* kMetaMaskOf = "sculpt.mask_of";

/// The grid to edit: the one named, else the default one.
const VdbGridEntry& chooseGrid(const VdbLayout& layout, const std::string& requested)
{
    if (!requested.empty()) {
        for (const VdbGridEntry& grid : layout.grids) {
            if (grid.name == requested) return grid;
        }
        throw InputError("has no grid named '" + requested + "' (it holds " + describeGrids(layout) + ")");
    }
    if (const VdbGridEntry* grid = defaultGrid(layout)) return *grid;
    if (levelSetNames(layout).empty()) {
        throw InputError("contains no float level-set grid (it holds " + describeGrids(layout) + ")");
    }
    throw InputError("holds several level sets and none is named 'surface' (" + describeGrids(layout) + "): choose one",
                     Remedy::ChooseGrid);
}

/// Refuses a chosen grid that cannot be a distance field.
void checkChosen(const VdbGridEntry& grid)
{
    if (!grid.isFloat())
        throw InputError("grid '" + grid.name + "' holds " + grid.type + " values, not float distances");
    if (grid.gridClass == "fog volume")
        throw InputError("grid '" + grid.name + "' is a fog volume (densities), not distances");
    if (!grid.instanceOf.empty()) {
        throw InputError("grid '" + grid.name + "' shares the voxels of grid '" + grid.instanceOf +
                         "' (an instance); open that grid instead");
    }
}

/// Every grid read is held in memory: refuse if their recorded sizes exceed what is available.
void requireMemoryFor(const VdbLayout& layout, const fs::path& path)
{
    double total = 0.0;
    for (const VdbGridEntry& grid : layout.grids) total += double(grid.memoryBytes);
    requireMemory(total, path.string());
}

/// A stream that throws on a short read: OpenVDB's File reader ignores some truncations and
/// leaves the missing voxels uninitialised.
template <typename Stream>
void throwOnShortReads(Stream& in)
{
    in.exceptions(std::ios::failbit | std::ios::badbit);
}

/// The decoded grids of a file and its metadata.
struct DecodedFile {
    openvdb::GridPtrVec grids;
    openvdb::MetaMap::Ptr metadata;
};

/// Walks a float grid's tree before OpenVDB reads it (see vdb_tree_check.h); `in` holds the
/// grid's bytes at their file positions.
void checkTree(std::istream& in, const VdbGridEntry& grid)
{
    throwOnShortReads(in);
    in.seekg(grid.transformBegin);
    BoundedReader bounded(in, grid.end);
    checkVdbFloatTree(bounded, grid.coding, /*throughBuffers=*/true, grid.buffersBegin != 0 ? grid.buffersBegin : -1);
}

/// Decodes one grid alone: the file's header and metadata, a grid count of one and that grid's
/// bytes go through OpenVDB's stream reader, so other grids (of types this build may not know)
/// are never touched. Float grids are walked first; other types go to OpenVDB unchecked. Both
/// read the bytes from memory (MemoryStream), read once.
DecodedFile decodeOne(const fs::path& path, const VdbLayout& layout, const VdbGridEntry& grid)
{
    std::ifstream file(path, std::ios::binary);
    throwOnShortReads(file);
    const std::int32_t one = 1;
    const std::int64_t head = layout.gridTableOffset + std::int64_t(sizeof one), size = head + grid.end - grid.begin;
    const std::unique_ptr<char[]> bytes(new char[std::size_t(size)]);  // the layout walk bounded it by the file
    file.read(bytes.get(), std::streamsize(layout.gridTableOffset));
    std::memcpy(bytes.get() + layout.gridTableOffset, &one, sizeof one);
    file.seekg(grid.begin);
    file.read(bytes.get() + head, std::streamsize(grid.end - grid.begin));
    if (grid.isFloat()) {
        MemoryStream gridBytes(bytes.get() + head, bytes.get() + size, grid.begin);
        checkTree(gridBytes, grid);
    }
    MemoryStream in(bytes.get(), bytes.get() + size);
    throwOnShortReads(in);
    openvdb::io::Stream stream(in, /*delayLoad=*/false);
    return {*stream.getGrids(), stream.getMetadata()};
}

/// The chosen grid and the others (decoded where this build can), warning of what cannot be kept.
std::pair<openvdb::FloatGrid::Ptr, VdbCompanions> decodeGrids(const fs::path& path, const VdbLayout& layout,
                                                              const VdbGridEntry& chosen,
                                                              std::vector<std::string>& warnings)
{
    DecodedFile file = decodeOne(path, layout, chosen);
    for (const VdbGridEntry& other : layout.grids) {
        if (&other == &chosen) continue;
        try {
            if (!openvdb::GridBase::isRegistered(other.type))
                throw std::runtime_error("type " + other.type + " unknown");
            if (!other.located()) throw std::runtime_error("a streamed file does not say where it ends");
            file.grids.push_back(decodeOne(path, layout, other).grids.front());
        } catch (const std::exception& e) {
            warnings.push_back(path.string() + ": grid '" + other.name + "' cannot be read by this build (" + e.what() +
                               "); it is left out of files saved from this one, which cannot replace this file");
        }
    }
    if (layout.unlocatedGrids > 0) {
        warnings.push_back(path.string() + ": " + std::to_string(layout.unlocatedGrids) +
                           " grids after those cannot be located; they are left out of files saved from this one, "
                           "which cannot replace this file");
    }
    auto grid = openvdb::gridPtrCast<openvdb::FloatGrid>(file.grids.front());
    if (!grid) throw InputError("grid '" + chosen.name + "' is unreadable");
    return {grid, VdbCompanions{{file.grids.begin() + 1, file.grids.end()}, *file.metadata}};
}

/// A float grid that is not a proper band (Mantaflow writes `phi` dense, background 0, in cell
/// units) rebuilt into one around its zero level, with a warning.
openvdb::FloatGrid::Ptr asNarrowBand(openvdb::FloatGrid::Ptr grid, const fs::path& path,
                                     std::vector<std::string>& warnings)
{
    const std::string why = whyNotNarrowBand(*grid);
    if (why.empty()) return grid;
    warnings.push_back(path.string() + ": grid '" + grid->getName() + "' is not a narrow-band level set (" + why +
                       "): rebuilt as a band of " + formatNumber(FieldImage::kDefaultHalfWidthVoxels) +
                       " voxels around its zero level");
    return rebuildNarrowBand(*grid, FieldImage::kDefaultHalfWidthVoxels);
}

/// Writing over a file that holds a grid this build cannot decode would lose that grid.
void refuseToLoseGrids(const fs::path& path)
{
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) return;
    VdbLayout layout;
    try {
        layout = scanVdbLayout(path);
    } catch (const InputError&) {
        return;  // not a readable .vdb: nothing in it could be kept anyway
    }
    for (const VdbGridEntry& grid : layout.grids) {
        if (!openvdb::GridBase::isRegistered(grid.type) || !grid.located()) {
            throw InputError(path.string() + ": holds grid '" + grid.name + "' that this build cannot read (" +
                             grid.type + "); writing over it would lose that grid: choose another file");
        }
    }
    if (layout.unlocatedGrids > 0) {
        throw InputError(path.string() + ": holds grids this build cannot locate (a streamed file); writing over it "
                                         "would lose them: choose another file");
    }
}

/// The level sets our files mark as pieces (their colour marks them).
openvdb::FloatGrid::Ptr asPieceGrid(const openvdb::GridBase::Ptr& grid)
{
    const auto levelSet = openvdb::gridPtrCast<openvdb::FloatGrid>(grid);
    return levelSet && levelSet->getMetadata<openvdb::Vec3SMetadata>(kMetaPieceColour) ? levelSet : nullptr;
}

/// A piece's own checksum (in its grid's metadata) checked, then dropped: edits outdate it.
void checkPieceChecksum(openvdb::FloatGrid& grid)
{
    if (auto sum = grid.getMetadata<openvdb::StringMetadata>(kMetaChecksum)) {
        if (sum->value() != formatChecksum(gridChecksum(grid)))
            throw InputError("corrupt (the voxels of piece '" + grid.getName() + "' do not match their checksum)");
        grid.removeMeta(kMetaChecksum);
    }
}

/// The grid a surface's mask is written as (null when nothing is masked): its tree shared, named
/// after the surface, marked as its mask, with its own checksum.
openvdb::GridBase::Ptr maskGridOf(const FieldImage& field, const std::string& surfaceName)
{
    if (!field.mask()) return nullptr;
    openvdb::FloatGrid::Ptr grid = field.maskPtr()->copy();
    grid->setName(surfaceName + ".mask");
    grid->insertMeta(kMetaMaskOf, openvdb::StringMetadata(surfaceName));
    grid->insertMeta(kMetaChecksum, openvdb::StringMetadata(formatChecksum(gridChecksum(*grid))));
    sealMetadata(*grid);
    return grid;
}

/// Takes the mask of the surface named `surfaceName` out of `grids` (if there is one) and gives
/// it to `field`, its checksum and lattice checked.
void attachMask(FieldImage& field, const std::string& surfaceName, openvdb::GridPtrVec& grids)
{
    const auto isMask = [&](const openvdb::GridBase::Ptr& grid) {
        const auto of = grid->getMetadata<openvdb::StringMetadata>(kMetaMaskOf);
        return of && of->value() == surfaceName && openvdb::gridPtrCast<openvdb::FloatGrid>(grid);
    };
    const auto found = std::find_if(grids.begin(), grids.end(), isMask);
    if (found == grids.end()) return;
    const openvdb::FloatGrid::Ptr mask = openvdb::gridPtrCast<openvdb::FloatGrid>(*found);
    checkMetadataSeal(*mask, "the mask of '" + surfaceName + "'");
    if (auto sum = mask->getMetadata<openvdb::StringMetadata>(kMetaChecksum)) {
        if (sum->value() != formatChecksum(gridChecksum(*mask)))
            throw InputError("corrupt (the mask of '" + surfaceName + "' does not match its checksum)");
    }
    for (const char* ours : {kMetaMaskOf, kMetaChecksum, kMetadataSealKey}) mask->removeMeta(ours);
    // Another program's grid may hold anything: a mask is a share in [0, 1], and not a number is none.
    for (auto it = mask->beginValueAll(); it; ++it) {
        if (!std::isfinite(*it)) it.setValue(0.0f);
        else if (*it < 0.0f || *it > 1.0f) it.setValue(std::clamp(*it, 0.0f, 1.0f));
    }
    mask->setName("mask");
    field.setMask(mask);
    grids.erase(found);
}

/// The file's version, and, for the grid it records as edited (`edited`), its voxel size and checksum.
void checkDocumentMetadata(const openvdb::MetaMap& meta, const FieldImage& field, const fs::path& path, bool edited)
{
    if (auto version = meta.getMetadata<openvdb::Int32Metadata>(kMetaVersion)) {
        if (version->value() > kVdbFormatVersion) {
            throw InputError(path.string() + ": written by a newer version of sculpt (format " +
                             std::to_string(version->value()) + ", this program reads up to " +
                             std::to_string(kVdbFormatVersion) + ")");
        }
    }
    if (auto frame = meta.getMetadata<openvdb::StringMetadata>(kVdbFrameKey);
        frame && frame->value() != FieldImage::kFrame)
        throw InputError(path.string() + ": its world is in the frame '" + frame->value() + "' (this program reads " +
                         FieldImage::kFrame + " documents)");
    if (!edited) return;
    if (auto size = meta.getMetadata<openvdb::DoubleMetadata>(kMetaVoxelSize)) {
        if (std::abs(size->value() - field.voxelSize()) > 1e-9 * field.voxelSize()) {
            throw InputError(path.string() + ": corrupt (voxel size in metadata " + formatNumber(size->value()) +
                             " differs from the grid's " + formatNumber(field.voxelSize()) + ")");
        }
    }
    if (auto sum = meta.getMetadata<openvdb::StringMetadata>(kMetaChecksum)) {
        if (sum->value() != formatChecksum(gridChecksum(field.grid()))) {
            throw InputError(path.string() + ": corrupt (voxel data does not match its checksum)");
        }
    }
}

/// Refused, naming the grid, if a value of it (a voxel or a tile, active or not) is not a finite
/// number: a NaN would reach measurements, meshes and other files.
void requireFiniteValues(const openvdb::FloatGrid& grid, const fs::path& path)
{
    const auto refuse = [&](float value, const std::string& where) {
        throw InputError(path.string() + ": grid '" + grid.getName() + "' holds a value that is not a finite number (" +
                         std::to_string(value) + " " + where + "): corrupt");
    };
    const auto at = [](const openvdb::Coord& c) {
        return "at voxel " + std::to_string(c.x()) + " " + std::to_string(c.y()) + " " + std::to_string(c.z());
    };
    for (auto leaf = grid.tree().cbeginLeaf(); leaf; ++leaf) {
        const float* values = leaf->buffer().data();
        for (openvdb::Index i = 0; i < leaf->SIZE; ++i)
            if (!std::isfinite(values[i])) refuse(values[i], at(leaf->offsetToGlobalCoord(i)));
    }
    forEachTileOffBackground(grid.tree(), [&](const openvdb::CoordBBox& block, float value, bool) {
        if (!std::isfinite(value)) refuse(value, at(block.min()));
    });
}

VdbDocument readUnchecked(const fs::path& path, const std::string& gridName)
{
    const VdbLayout layout = scanVdbLayout(path);
    const VdbGridEntry& chosen = chooseGrid(layout, gridName);
    checkChosen(chosen);
    requireMemoryFor(layout, path);

    std::vector<std::string> warnings;
    auto [grid, companions] = decodeGrids(path, layout, chosen, warnings);
    openvdb::MetaMap& meta = companions.metadata;
    checkMetadataSeal(meta, "its metadata");
    checkMetadataSeal(*grid, "grid '" + chosen.name + "'");
    std::string units = FieldImage::kDefaultUnits;
    if (auto u = meta.getMetadata<openvdb::StringMetadata>(kMetaUnits)) units = u->value();
    if (const std::string problem = unitsProblem(units); !problem.empty())
        throw InputError(path.string() + ": its length unit (" + kMetaUnits + ") cannot be: " + problem);
    checkPieceChecksum(*grid);
    requireFiniteValues(*grid, path);
    FieldImage field(asNarrowBand(grid, path, warnings), units);
    checkDocumentMetadata(meta, field, path, layout.editedGrid.empty() || layout.editedGrid == chosen.name);
    attachMask(field, chosen.name, companions.grids);
    for (const char* ours :
         {kMetaVersion, kMetaUnits, kVdbFrameKey, kMetaVoxelSize, kMetaChecksum, kVdbEditedGridKey, kMetadataSealKey}) {
        meta.removeMeta(ours);
    }
    return {std::move(field), std::move(companions), std::move(warnings)};
}

/// A piece with the look its grid's metadata records (the defaults where it records none).
/// Refused (naming the piece and the field) if the look cannot be: a colour outside 0..1 or not a
/// number, a placement placementProblem refuses.
Piece pieceOf(FieldImage field, const fs::path& path)
{
    const openvdb::FloatGrid& grid = field.grid();
    if (const std::string problem = pieceNameProblem(grid.getName()); !grid.getName().empty() && !problem.empty())
        throw InputError(path.string() + ": a piece's name (its grid's name) cannot be: " + problem);
    Piece piece{{grid.getName().empty() ? "surface" : grid.getName()}, std::move(field)};
    const std::string where = path.string() + ": piece '" + piece.name + "': ";
    if (auto colour = grid.getMetadata<openvdb::Vec3SMetadata>(kMetaPieceColour)) {
        piece.colour = colour->value();
        for (int c = 0; c < 3; ++c)
            if (!(piece.colour[c] >= 0.0f && piece.colour[c] <= 1.0f))
                throw InputError(where + "its colour (" + kMetaPieceColour + ") is not three numbers from 0 to 1");
    }
    if (auto visible = grid.getMetadata<openvdb::BoolMetadata>(kMetaPieceVisible)) piece.visible = visible->value();
    if (auto placement = grid.getMetadata<openvdb::Mat4DMetadata>(kMetaPiecePlacement)) {
        piece.placement = placement->value();
        if (const std::string problem = placementProblem(piece.placement); !problem.empty())
            throw InputError(where + "its placement (" + kMetaPiecePlacement + ") cannot be: " + problem);
    }
    if (auto label = grid.getMetadata<openvdb::Int32Metadata>(kMetaPieceLabel)) {
        piece.label = label->value();
        if (piece.label < 1 || piece.label > kMaxPieceLabel) {
            throw InputError(where + "its label value (" + kMetaPieceLabel + ") is not a whole number from 1 to " +
                             std::to_string(kMaxPieceLabel));
        }
    }
    return piece;
}

/// The grid a piece is written as: its tree shared, its name and look in its metadata, and its
/// checksum unless it is the edited grid (`ownChecksum` false), which the file's checksum covers.
openvdb::FloatGrid::Ptr pieceGrid(const Piece& piece, bool ownChecksum)
{
    openvdb::FloatGrid::Ptr grid = openvdb::ConstPtrCast<openvdb::FloatGrid>(piece.field.gridPtr())->copy();
    grid->setName(piece.name);
    grid->insertMeta(kMetaPieceColour, openvdb::Vec3SMetadata(piece.colour));
    grid->insertMeta(kMetaPieceVisible, openvdb::BoolMetadata(piece.visible));
    grid->insertMeta(kMetaPiecePlacement, openvdb::Mat4DMetadata(piece.placement));
    grid->removeMeta(kMetaPieceLabel);
    if (piece.label > 0) grid->insertMeta(kMetaPieceLabel, openvdb::Int32Metadata(piece.label));
    grid->removeMeta(kMetaChecksum);  // one copied from the file the piece came from would be stale
    if (ownChecksum) grid->insertMeta(kMetaChecksum, openvdb::StringMetadata(formatChecksum(gridChecksum(*grid))));
    sealMetadata(*grid);
    return grid;
}

/// Every piece's values, seal and checksum, checked side by side (a checksum reads all of a
/// piece's tiles, a millisecond for a small one; a label map's document has thousands); the
/// first piece refused, in file order, is named.
void checkPieceGrids(const std::vector<openvdb::FloatGrid::Ptr>& levelSets, const fs::path& path)
{
    std::vector<std::exception_ptr> refused(levelSets.size());
    tbb::parallel_for(std::size_t(0), levelSets.size(), [&](std::size_t i) {
        try {
            requireFiniteValues(*levelSets[i], path);
            try {
                checkMetadataSeal(*levelSets[i], "piece '" + levelSets[i]->getName() + "'");
                checkPieceChecksum(*levelSets[i]);
            } catch (const InputError& e) {
                throw InputError(path.string() + ": " + e.what());
            }
        } catch (...) {
            refused[i] = std::current_exception();
        }
    });
    for (const std::exception_ptr& refusal : refused)
        if (refusal) std::rethrow_exception(refusal);
}

void checkPieceNames(const std::vector<Piece>& pieces, const fs::path& path)
{
    if (pieces.empty()) throw InputError(path.string() + ": a document needs at least one piece");
    std::set<std::string> names;
    for (const Piece& piece : pieces) {
        if (const std::string problem = pieceNameProblem(piece.name); !problem.empty())
            throw InputError(path.string() + ": a piece's name cannot be: " + problem);
        if (!names.insert(piece.name).second)
            throw InputError(path.string() + ": two pieces are named '" + piece.name + "'");
    }
}

}  // namespace

VdbDocument readVdbDocument(const fs::path& path, const std::string& gridName)
{
    openvdb::initialize();
    std::error_code ec;
    if (!fs::exists(path, ec)) throw InputError(path.string() + ": no such file");
    if (!fs::is_regular_file(path, ec)) throw InputError(path.string() + ": not a regular file");
    try {
        return readUnchecked(path, gridName);
    } catch (const InputError& e) {
        const std::string what = e.what();
        if (what.rfind(path.string(), 0) == 0) throw;
        throw InputError(path.string() + ": " + what, e.remedy());
    } catch (const std::ios_base::failure&) {
        throw InputError(path.string() + ": truncated (the file ends inside its voxel data)");
    } catch (const std::bad_alloc&) {
        throw InputError(path.string() + ": corrupt (it asks for more memory than is available)");
    } catch (const std::exception& e) {
        throw InputError(path.string() + ": not a valid OpenVDB file, or truncated or corrupt (" + e.what() + ")");
    }
}

VdbPieces readVdbPieces(const fs::path& path, const std::string& gridName)
{
    VdbDocument document = readVdbDocument(path, gridName);
    const std::string units = document.field.units();
    VdbPieces read{{pieceOf(std::move(document.field), path)},
                   {{}, std::move(document.companions.metadata)},
                   std::move(document.warnings)};
    std::vector<openvdb::FloatGrid::Ptr> levelSets;
    for (const openvdb::GridBase::Ptr& grid : document.companions.grids) {
        if (const openvdb::FloatGrid::Ptr levelSet = asPieceGrid(grid)) levelSets.push_back(levelSet);
        else read.companions.grids.push_back(grid);  // masks are taken out as their pieces are made
    }
    checkPieceGrids(levelSets, path);
    for (const openvdb::FloatGrid::Ptr& levelSet : levelSets) {
        FieldImage field = [&] {
            try {
                FieldImage piece(levelSet, units);  // refuses a background that is not a number
                attachMask(piece, levelSet->getName(), read.companions.grids);
                return piece;
            } catch (const InputError& e) {
                throw InputError(path.string() + ": " + e.what());
            }
        }();
        read.pieces.push_back(pieceOf(std::move(field), path));
    }
    return read;
}

FieldImage readFieldImage(const fs::path& path, const std::string& gridName)
{
    return readVdbDocument(path, gridName).field;
}

void writeFieldImage(const FieldImage& field, const fs::path& path, const VdbCompanions& companions)
{
    openvdb::initialize();
    refuseToLoseGrids(path);
    AtomicFile out(path);
    openvdb::MetaMap meta = companions.metadata;
    meta.insertMeta(kMetaVersion, openvdb::Int32Metadata(kVdbFormatVersion));
    meta.insertMeta(kMetaUnits, openvdb::StringMetadata(field.units()));
    meta.insertMeta(kVdbFrameKey, openvdb::StringMetadata(FieldImage::kFrame));
    meta.insertMeta(kMetaVoxelSize, openvdb::DoubleMetadata(field.voxelSize()));
    meta.insertMeta(kMetaChecksum, openvdb::StringMetadata(formatChecksum(gridChecksum(field.grid()))));
    // A shallow copy (the tree is shared) carries the name documents promise and the grid's seal.
    auto edited = openvdb::ConstPtrCast<openvdb::FloatGrid>(field.gridPtr())->copy();
    if (edited->getName().empty()) edited->setName("surface");
    sealMetadata(*edited);
    openvdb::GridCPtrVec grids{edited};
    meta.insertMeta(kVdbEditedGridKey, openvdb::StringMetadata(grids.front()->getName()));
    sealMetadata(meta);
    if (auto mask = maskGridOf(field, grids.front()->getName())) grids.push_back(mask);
    grids.insert(grids.end(), companions.grids.begin(), companions.grids.end());
    try {
        openvdb::io::File file(out.temporaryPath().string());
        file.write(grids, meta);
        file.close();
        stampContentUuid(out.temporaryPath());
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        throw InputError(path.string() + ": cannot write (" + e.what() + ")");
    }
    out.commit();
}

void writeVdbPieces(const std::vector<Piece>& pieces, const fs::path& path, const VdbCompanions& companions)
{
    checkPieceNames(pieces, path);
    // Each piece's checksum reads all its tiles (a millisecond for a small one): thousands of
    // pieces (a label map's) are sealed side by side.
    std::vector<openvdb::FloatGrid::Ptr> sealed(pieces.size());
    tbb::parallel_for(std::size_t(1), pieces.size(), [&](std::size_t i) { sealed[i] = pieceGrid(pieces[i], true); });
    VdbCompanions others{{}, companions.metadata};
    for (std::size_t i = 1; i < pieces.size(); ++i) {
        others.grids.push_back(sealed[i]);
        if (auto mask = maskGridOf(pieces[i].field, pieces[i].name)) others.grids.push_back(mask);
    }
    others.grids.insert(others.grids.end(), companions.grids.begin(), companions.grids.end());
    FieldImage first(pieceGrid(pieces.front(), false), pieces.front().field.units());
    first.setMask(pieces.front().field.maskPtr());
    writeFieldImage(first, path, others);
}

}  // namespace sculpt
