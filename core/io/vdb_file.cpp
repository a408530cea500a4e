#include "core/io/vdb_file.h"

#include "core/base/atomic_file.h"
#include "core/base/errors.h"
#include "core/base/memory_budget.h"
#include "core/base/text_format.h"
#include "core/field/grid_checksum.h"

#include <openvdb/io/File.h>
#include <openvdb/io/Stream.h>

#include <cmath>
#include <fstream>
#include <sstream>

namespace sculpt {

namespace fs = std::filesystem;

namespace {

constexpr const char* kMetaVersion = "sculpt.format_version";
constexpr const char* kMetaUnits = "sculpt.units";
constexpr const char* kMetaVoxelSize = "sculpt.voxel_size";
constexpr const char* kMetaChecksum = "sculpt.checksum";

/// First float level-set grid among the file's grid descriptors (metadata only, no voxels).
openvdb::GridBase::Ptr findLevelSet(const openvdb::GridPtrVec& grids)
{
    for (const auto& grid : grids) {
        if (grid->isType<openvdb::FloatGrid>() && grid->getGridClass() == openvdb::GRID_LEVEL_SET) {
            return grid;
        }
    }
    throw InputError("contains no float level-set grid");
}

/// All grids of the file get loaded: refuse if their recorded in-core size exceeds memory.
void requireMemoryFor(const openvdb::GridPtrVec& grids, const fs::path& path)
{
    double total = 0.0;
    for (const auto& grid : grids) {
        const auto bytes = grid->getMetadata<openvdb::Int64Metadata>(openvdb::GridBase::META_FILE_MEM_BYTES);
        if (bytes && bytes->value() < 0) throw InputError("corrupt (negative grid size)");
        if (bytes) total += double(bytes->value());
    }
    requireMemory(total, path.string());
}

void checkDocumentMetadata(const openvdb::MetaMap& meta, const FieldImage& field, const fs::path& path)
{
    if (auto version = meta.getMetadata<openvdb::Int32Metadata>(kMetaVersion)) {
        if (version->value() > kVdbFormatVersion) {
            throw InputError(path.string() + ": written by a newer version of sculpt (format " +
                             std::to_string(version->value()) + ", this program reads up to " +
                             std::to_string(kVdbFormatVersion) + ")");
        }
    }
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

/// Reads every grid with a stream that throws on a short read: OpenVDB's own File reader
/// ignores some truncations and leaves the missing voxels uninitialised.
openvdb::GridPtrVecPtr readAllGridsStrictly(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    in.exceptions(std::ios::failbit | std::ios::badbit);
    openvdb::io::Stream stream(in, /*delayLoad=*/false);
    return stream.getGrids();
}

FieldImage readUnchecked(const fs::path& path)
{
    // Headers first (no voxels): refuse files without a level set or too big for memory.
    openvdb::io::File file(path.string());
    file.open(/*delayLoad=*/false);
    const auto meta = file.getMetadata();
    const openvdb::GridPtrVecPtr descriptors = file.readAllGridMetadata();
    const auto descriptor = findLevelSet(*descriptors);
    requireMemoryFor(*descriptors, path);
    file.close();

    openvdb::FloatGrid::Ptr grid;
    const openvdb::GridPtrVecPtr grids = readAllGridsStrictly(path);
    for (const auto& candidate : *grids) {
        if (candidate->getName() == descriptor->getName()) {
            grid = openvdb::gridPtrCast<openvdb::FloatGrid>(candidate);
            break;
        }
    }
    if (!grid) throw InputError("grid '" + descriptor->getName() + "' is unreadable");

    std::string units = FieldImage::kDefaultUnits;
    if (auto u = meta->getMetadata<openvdb::StringMetadata>(kMetaUnits)) units = u->value();
    FieldImage field(grid, units);
    checkDocumentMetadata(*meta, field, path);
    return field;
}

}  // namespace

FieldImage readFieldImage(const fs::path& path)
{
    openvdb::initialize();
    std::error_code ec;
    if (!fs::exists(path, ec)) throw InputError(path.string() + ": no such file");
    if (!fs::is_regular_file(path, ec)) throw InputError(path.string() + ": not a regular file");
    try {
        return readUnchecked(path);
    } catch (const InputError& e) {
        const std::string what = e.what();
        if (what.rfind(path.string(), 0) == 0) throw;
        throw InputError(path.string() + ": " + what);
    } catch (const std::ios_base::failure&) {
        throw InputError(path.string() + ": truncated (the file ends inside its voxel data)");
    } catch (const std::bad_alloc&) {
        throw InputError(path.string() + ": corrupt (it asks for more memory than is available)");
    } catch (const std::exception& e) {
        throw InputError(path.string() + ": not a valid OpenVDB file, or truncated or corrupt (" + e.what() + ")");
    }
}

void writeFieldImage(const FieldImage& field, const fs::path& path)
{
    openvdb::initialize();
    AtomicFile out(path);
    openvdb::MetaMap meta;
    meta.insertMeta(kMetaVersion, openvdb::Int32Metadata(kVdbFormatVersion));
    meta.insertMeta(kMetaUnits, openvdb::StringMetadata(field.units()));
    meta.insertMeta(kMetaVoxelSize, openvdb::DoubleMetadata(field.voxelSize()));
    meta.insertMeta(kMetaChecksum, openvdb::StringMetadata(formatChecksum(gridChecksum(field.grid()))));
    try {
        openvdb::io::File file(out.temporaryPath().string());
        file.write(openvdb::GridCPtrVec{field.gridPtr()}, meta);
        file.close();
    } catch (const std::exception& e) {
        throw InputError(path.string() + ": cannot write (" + e.what() + ")");
    }
    out.commit();
}

}  // namespace sculpt
