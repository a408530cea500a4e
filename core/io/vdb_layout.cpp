#include "core/io/vdb_layout.h"

#include "core/base/errors.h"

#include <openvdb/Grid.h>
#include <openvdb/io/GridDescriptor.h>
#include <openvdb/openvdb.h>
#include <openvdb/version.h>

#include <algorithm>
#include <fstream>

namespace sculpt {

namespace fs = std::filesystem;

namespace {

/// Reads little-endian fields as OpenVDB writes them, refusing any length that runs past the end.
class BoundedReader {
public:
    explicit BoundedReader(const fs::path& path) : mIn(path, std::ios::binary), mSize(std::int64_t(fs::file_size(path)))
    {
        mIn.exceptions(std::ios::failbit | std::ios::badbit);
    }

    std::int64_t size() const { return mSize; }
    std::int64_t position() { return std::int64_t(mIn.tellg()); }
    std::int64_t remaining() { return mSize - position(); }

    template <typename T>
    T read(const char* what)
    {
        need(sizeof(T), what);
        T value;
        mIn.read(reinterpret_cast<char*>(&value), sizeof(T));
        return value;
    }

    std::string readBytes(std::int64_t length, const char* what)
    {
        need(length, what);
        std::string bytes(std::size_t(length), '\0');
        mIn.read(bytes.data(), std::streamsize(length));
        return bytes;
    }

    std::string readString(const char* what) { return readBytes(read<std::uint32_t>(what), what); }

    void skip(std::int64_t bytes, const char* what)
    {
        need(bytes, what);
        mIn.seekg(bytes, std::ios::cur);
    }

    void seek(std::int64_t at, const char* what)
    {
        if (at < position() || at > mSize)
            throw InputError(std::string("corrupt (") + what + " points outside the file)");
        mIn.seekg(at);
    }

private:
    void need(std::int64_t bytes, const char* what)
    {
        const std::int64_t left = remaining();
        if (bytes < 0 || bytes > left) {
            throw InputError(std::string("truncated or corrupt (") + what + " needs " + std::to_string(bytes) +
                             " bytes, " + std::to_string(left) + " remain)");
        }
    }

    std::ifstream mIn;
    std::int64_t mSize;
};

/// The file header up to the file metadata; returns the format version and whether grids have offsets.
std::pair<std::uint32_t, bool> readHeader(BoundedReader& in)
{
    if (in.size() < 8 || in.read<std::int64_t>("the header") != openvdb::OPENVDB_MAGIC) {
        throw InputError("not an OpenVDB file");
    }
    const auto version = in.read<std::uint32_t>("the header");
    if (version > openvdb::OPENVDB_FILE_VERSION) {
        throw InputError("written by a newer OpenVDB (file format " + std::to_string(version) +
                         ", this build reads up to " + std::to_string(openvdb::OPENVDB_FILE_VERSION) + ")");
    }
    if (version < openvdb::OPENVDB_FILE_VERSION_FLOAT_FRUSTUM_BBOX) {
        throw InputError("an OpenVDB file of format " + std::to_string(version) +
                         ", older than OpenVDB reads (221, from 2013)");
    }
    in.skip(2 * sizeof(std::uint32_t), "the header");  // library version
    const bool hasOffsets = in.read<char>("the header") != 0;
    if (version < openvdb::OPENVDB_FILE_VERSION_NODE_MASK_COMPRESSION) in.skip(1, "the header");  // compression flag
    in.skip(36, "the header");                                                                    // uuid
    return {version, hasOffsets};
}

/// The entries of a metadata map we use; the others are skipped.
struct MetadataSeen {
    std::string gridClass;         // a grid's "class"
    std::string editedGrid;        // the file's "sculpt.grid"
    std::int64_t memoryBytes = 0;  // a grid's "file_mem_bytes"
};

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
        if (name == openvdb::GridBase::META_GRID_CLASS && type == "string") {
            seen.gridClass = in.readBytes(bytes, "a metadata value");
        } else if (name == kVdbEditedGridKey && type == "string") {
            seen.editedGrid = in.readBytes(bytes, "a metadata value");
        } else if (name == openvdb::GridBase::META_FILE_MEM_BYTES && type == "int64" && bytes == 8) {
            seen.memoryBytes = in.read<std::int64_t>("a metadata value");
            if (seen.memoryBytes < 0) throw InputError("corrupt (negative grid size)");
        } else {
            in.skip(bytes, "a metadata value");
        }
    }
    return seen;
}

/// A grid's descriptor and, where the file has offsets, its metadata; leaves `in` after the grid.
VdbGridEntry readGrid(BoundedReader& in, std::uint32_t version, bool hasOffsets)
{
    VdbGridEntry grid;
    grid.begin = in.position();
    grid.name = openvdb::io::GridDescriptor::stripSuffix(in.readString("a grid name"));
    grid.type = in.readString("a grid type");
    const std::string halfSuffix = "_HalfFloat";
    if (grid.type.size() > halfSuffix.size() &&
        grid.type.compare(grid.type.size() - halfSuffix.size(), halfSuffix.size(), halfSuffix) == 0) {
        grid.type.resize(grid.type.size() - halfSuffix.size());
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
    if (version >= openvdb::OPENVDB_FILE_VERSION_NODE_MASK_COMPRESSION) in.skip(4, "a grid's compression");
    const MetadataSeen seen = readMetadata(in);
    grid.gridClass = seen.gridClass;
    grid.memoryBytes = seen.memoryBytes;
    if (hasOffsets) {
        in.seek(endPos, "a grid offset");
        grid.end = endPos;
    }
    return grid;
}

}  // namespace

bool VdbGridEntry::isFloat() const { return type == openvdb::FloatGrid::gridType(); }

VdbLayout scanVdbLayout(const fs::path& path)
{
    BoundedReader in(path);
    VdbLayout layout;
    layout.fileSize = in.size();
    const auto [version, hasOffsets] = readHeader(in);
    layout.hasGridOffsets = hasOffsets;
    layout.editedGrid = readMetadata(in).editedGrid;
    layout.gridTableOffset = in.position();
    const auto count = in.read<std::int32_t>("the grid count");
    // A descriptor holds at least three 4-byte lengths and three 8-byte offsets.
    if (count < 0 || std::int64_t(count) * 36 > in.remaining()) throw InputError("corrupt (impossible grid count)");
    // Without offsets, grids after the first cannot be found without decoding it.
    const std::int32_t scanned = hasOffsets ? count : std::min(count, 1);
    for (std::int32_t i = 0; i < scanned; ++i) layout.grids.push_back(readGrid(in, version, hasOffsets));
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
    return text.empty() ? "no grids" : text;
}

}  // namespace sculpt
