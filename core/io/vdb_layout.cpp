// SPDX-License-Identifier: Apache-2.0
#include "core/io/vdb_layout.h"

#include "core/base/errors.h"
#include "core/io/bounded_reader.h"
#include "core/io/vdb_tree_check.h"

#include <openvdb/Grid.h>
#include <openvdb/io/DelayedLoadMetadata.h>
#include <openvdb/io/GridDescriptor.h>
#include <openvdb/openvdb.h>
#include <openvdb/version.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <limits>

namespace sculpt {

namespace fs = std::filesystem;

namespace {

/// The file header up to the file metadata; returns whether grids have offsets.
bool readHeader(BoundedReader& in)
{
    if (in.size() < 8 || in.read<std::int64_t>("the header") != openvdb::OPENVDB_MAGIC) {
        throw InputError("not an OpenVDB file");
    }
    const auto version = in.read<std::uint32_t>("the header");
    if (version > openvdb::OPENVDB_FILE_VERSION) {
        throw InputError("written by a newer OpenVDB (file format " + std::to_string(version) +
                         ", this build reads up to " + std::to_string(openvdb::OPENVDB_FILE_VERSION) + ")");
    }
    if (version < openvdb::OPENVDB_FILE_VERSION_NODE_MASK_COMPRESSION) {
        throw InputError("an OpenVDB file of format " + std::to_string(version) +
                         ", older than this program reads (222, OpenVDB 2.0 from 2013)");
    }
    in.skip(2 * sizeof(std::uint32_t), "the header");  // library version
    const bool hasOffsets = in.read<char>("the header") != 0;
    in.skip(36, "the header");  // uuid
    return hasOffsets;
}

/// OpenVDB's delayed-load table ("__delayedload": a leaf count, then a mask byte and a
/// compressed size per leaf, each part raw or Blosc-compressed, the sizes optional). Its reader
/// allocates for the count, and for the size a Blosc header claims, before reading, so both are
/// held to the leaves the rest of the file could hold (each stores at least its 64-byte value
/// mask; OpenVDB's own sizes part may hold more entries than leaves), and each part to the
/// value's bytes.
void checkDelayedLoad(BoundedReader& in, std::uint32_t bytes)
{
    if (bytes == 0) return;
    const std::int64_t end = in.position() + bytes;
    const auto count = in.read<std::uint32_t>("a delayed-load table");
    if (std::int64_t(count) * 64 > in.size() - end)
        throw InputError("corrupt (a delayed-load table for more leaves than the file holds)");
    const auto part = [&](std::uint32_t stored, std::int64_t itemBytes) {
        if (stored == 0) {  // raw
            in.skip(std::int64_t(count) * itemBytes, "a delayed-load table");
            return;
        }
        constexpr std::int64_t kBloscHeader = 16;  // version, flags, type size, then 4 bytes of size
        std::uint32_t unpacked = 0;
        if (stored >= kBloscHeader) {
            const std::string header = in.readBytes(kBloscHeader, "a delayed-load table");
            std::memcpy(&unpacked, header.data() + 4, sizeof unpacked);
        }
        if (stored < kBloscHeader || std::int64_t(unpacked) / itemBytes * 64 > in.size() - end)
            throw InputError("corrupt (a delayed-load table's compressed part unpacks to more than the file holds)");
        in.skip(std::int64_t(stored) - kBloscHeader, "a delayed-load table");
    };
    part(in.read<std::uint32_t>("a delayed-load table"), sizeof(openvdb::io::DelayedLoadMetadata::MaskType));
    const auto sizes = in.read<std::uint32_t>("a delayed-load table");  // all ones: no sizes stored
    if (sizes != std::numeric_limits<std::uint32_t>::max())
        part(sizes, sizeof(openvdb::io::DelayedLoadMetadata::CompressedSizeType));
    if (in.position() > end) throw InputError("corrupt (a delayed-load table overruns its metadata)");
    in.seek(end, "a delayed-load table");
}

/// The entries of a metadata map we use; the others are skipped.
struct MetadataSeen {
    std::string gridClass;         // a grid's "class"
    std::string editedGrid;        // the file's "sculpt.grid"
    std::string frame;             // the file's "sculpt.frame"
    std::int64_t memoryBytes = 0;  // a grid's "file_mem_bytes"
};

/// OpenVDB reads a value of a fixed-size type (int32, vec3d, mat4d, ...) by its type's size,
/// whatever length the file gives it: a length that differs would leave OpenVDB reading the next
/// entry from the wrong place (a name "of 1.7 GB"), so it is refused here. Strings, the
/// delayed-load table and types this build does not know are read by their length.
void requireValueSize(const std::string& type, std::uint32_t bytes)
{
    if (type == "string" || type == openvdb::io::DelayedLoadMetadata::staticTypeName() ||
        !openvdb::Metadata::isRegisteredType(type))
        return;
    const openvdb::Metadata::Ptr value = openvdb::Metadata::createMetadata(type);
    if (bytes != value->size()) {
        throw InputError("corrupt (a metadata value of type " + type + " is " + std::to_string(bytes) +
                         " bytes long, not " + std::to_string(value->size()) + ")");
    }
}

MetadataSeen readMetadata(BoundedReader& in)
{
    MetadataSeen seen;
    const auto count = in.read<std::uint32_t>("a metadata count");
    // Every entry holds at least three 4-byte lengths.
    if (std::int64_t(count) * 12 > in.remaining()) throw InputError("corrupt (more metadata entries than bytes)");
    for (std::uint32_t i = 0; i < count; ++i) {
        const std::string name = in.readString("a metadata name");
        const std::string type = in.readString("a metadata type");
        const auto bytes = in.read<std::uint32_t>("a metadata value");
        requireValueSize(type, bytes);
        if (name == openvdb::GridBase::META_GRID_CLASS && type == "string") {
            seen.gridClass = in.readBytes(bytes, "a metadata value");
        } else if (name == kVdbEditedGridKey && type == "string") {
            seen.editedGrid = in.readBytes(bytes, "a metadata value");
        } else if (name == kVdbFrameKey && type == "string") {
            seen.frame = in.readBytes(bytes, "a metadata value");
        } else if (name == openvdb::GridBase::META_FILE_MEM_BYTES && type == "int64" && bytes == 8) {
            seen.memoryBytes = in.read<std::int64_t>("a metadata value");
            if (seen.memoryBytes < 0) throw InputError("corrupt (negative grid size)");
        } else if (type == openvdb::io::DelayedLoadMetadata::staticTypeName()) {
            checkDelayedLoad(in, bytes);
        } else {
            in.skip(bytes, "a metadata value");
        }
    }
    return seen;
}

/// A grid's descriptor and metadata; leaves `in` after the grid. A streamed file (no offsets)
/// is walked to the grid's end, which only a float tree's walk can find.
VdbGridEntry readGrid(BoundedReader& in, bool hasOffsets)
{
    VdbGridEntry grid;
    grid.begin = in.position();
    grid.name = openvdb::io::GridDescriptor::stripSuffix(in.readString("a grid name"));
    grid.type = in.readString("a grid type");
    const std::string halfSuffix = "_HalfFloat";
    if (grid.type.size() > halfSuffix.size() &&
        grid.type.compare(grid.type.size() - halfSuffix.size(), halfSuffix.size(), halfSuffix) == 0) {
        grid.type.resize(grid.type.size() - halfSuffix.size());
        grid.coding.halfFloat = true;
    }
    grid.instanceOf = openvdb::io::GridDescriptor::stripSuffix(in.readString("a grid's instance parent"));
    const auto gridPos = in.read<std::int64_t>("a grid offset");
    const auto blockPos = in.read<std::int64_t>("a grid offset");
    const auto endPos = in.read<std::int64_t>("a grid offset");
    if (hasOffsets) {
        if (gridPos < in.position() || blockPos < gridPos || endPos < blockPos || endPos > in.size()) {
            throw InputError("truncated or corrupt (grid '" + grid.name +
                             "' ends beyond the file, or its offsets are out of order)");
        }
        in.seek(gridPos, "a grid offset");
    }
    grid.coding.compression = in.read<std::uint32_t>("a grid's compression");
    const MetadataSeen seen = readMetadata(in);
    grid.gridClass = seen.gridClass;
    grid.memoryBytes = seen.memoryBytes;
    grid.transformBegin = in.position();
    if (hasOffsets) {
        in.seek(endPos, "a grid offset");
        grid.buffersBegin = blockPos;
        grid.end = endPos;
    } else if (grid.isFloat() && grid.instanceOf.empty()) {
        checkVdbFloatTree(in, grid.coding, /*throughBuffers=*/true);
        grid.end = in.position();
    }
    return grid;
}

}  // namespace

bool VdbGridEntry::isFloat() const { return type == openvdb::FloatGrid::gridType(); }

VdbLayout scanVdbLayout(const fs::path& path)
{
    std::ifstream file(path, std::ios::binary);
    file.exceptions(std::ios::failbit | std::ios::badbit);
    BoundedReader in(file, std::int64_t(fs::file_size(path)));
    VdbLayout layout;
    layout.fileSize = in.size();
    const bool hasOffsets = readHeader(in);
    const MetadataSeen fileMetadata = readMetadata(in);
    layout.editedGrid = fileMetadata.editedGrid;
    layout.frame = fileMetadata.frame;
    layout.gridTableOffset = in.position();
    const auto count = in.read<std::int32_t>("the grid count");
    // A descriptor holds at least three 4-byte lengths and three 8-byte offsets.
    if (count < 0 || std::int64_t(count) * 36 > in.remaining()) throw InputError("corrupt (impossible grid count)");
    for (std::int32_t i = 0; i < count; ++i) {
        layout.grids.push_back(readGrid(in, hasOffsets));
        if (!layout.grids.back().located()) {
            layout.unlocatedGrids = count - i - 1;
            break;
        }
    }
    return layout;
}

const VdbGridEntry* defaultGrid(const VdbLayout& layout)
{
    for (const std::string& name : {layout.editedGrid, std::string("surface")}) {
        for (const VdbGridEntry& grid : layout.grids) {
            if (!name.empty() && grid.name == name) return &grid;
        }
    }
    const VdbGridEntry* only = nullptr;
    for (const VdbGridEntry& grid : layout.grids) {
        if (!grid.isFloat() || !grid.isLevelSet()) continue;
        if (only) return nullptr;
        only = &grid;
    }
    return only;
}

std::vector<std::string> levelSetNames(const VdbLayout& layout)
{
    std::vector<std::string> names;
    for (const VdbGridEntry& grid : layout.grids) {
        if (grid.isFloat() && grid.isLevelSet()) names.push_back(grid.name);
    }
    return names;
}

std::string describeGrids(const VdbLayout& layout)
{
    std::string text;
    for (const VdbGridEntry& grid : layout.grids) {
        if (!text.empty()) text += ", ";
        text += "'" + grid.name + "' (" + (grid.gridClass.empty() ? grid.type : grid.gridClass) + ")";
    }
    if (layout.unlocatedGrids > 0) {
        text += " and " + std::to_string(layout.unlocatedGrids) + " more that a streamed file does not locate";
    }
    return text.empty() ? "no grids" : text;
}

}  // namespace sculpt
