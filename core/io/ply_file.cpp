// SPDX-License-Identifier: Apache-2.0
#include "core/io/ply_file.h"

#include "core/base/errors.h"
#include "core/base/text_format.h"
#include "core/io/byte_order.h"
#include "core/io/text_lines.h"
#include "core/mesh/polygon_soup.h"

#include <cmath>
#include <fstream>
#include <optional>

namespace sculpt {

namespace fs = std::filesystem;

namespace {

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

std::size_t sizeOf(PlyType type)
{
    switch (type) {
    case PlyType::Int8:
    case PlyType::UInt8: return 1;
    case PlyType::Int16:
    case PlyType::UInt16: return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32: return 4;
    case PlyType::Float64: return 8;
    }
    return 0;
}

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::Float32;   // the items' type, for a list
    std::optional<PlyType> countType;  // set for a list
};

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> properties;

    /// Bytes an element takes at least in a binary body (lists empty).
    std::size_t minimalBytes() const
    {
        std::size_t bytes = 0;
        for (const PlyProperty& p : properties) bytes += sizeOf(p.countType.value_or(p.type));
        return bytes;
    }
};

enum class PlyFormat { Text, LittleEndian, BigEndian };

struct PlyHeader {
    PlyFormat format = PlyFormat::Text;
    std::vector<PlyElement> elements;
    std::size_t bodyOffset = 0;
    int bodyLine = 0;  // the body's first line, for a text body's messages

    std::uint64_t countOf(const std::string& name) const
    {
        for (const PlyElement& e : elements) {
            if (e.name == name) return e.count;
        }
        return 0;
    }
};

PlyType typeNamed(std::string_view name, const TextLines& lines)
{
    static const std::pair<std::string_view, PlyType> names[] = {
        {"char", PlyType::Int8},      {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
        {"uint8", PlyType::UInt8},    {"short", PlyType::Int16},     {"int16", PlyType::Int16},
        {"ushort", PlyType::UInt16},  {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
        {"int32", PlyType::Int32},    {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
        {"float", PlyType::Float32},  {"float32", PlyType::Float32}, {"double", PlyType::Float64},
        {"float64", PlyType::Float64}};
    for (const auto& [word, type] : names) {
        if (word == name) return type;
    }
    lines.fail("unknown PLY property type '" + std::string(name) + "'");
}

PlyFormat formatNamed(std::string_view name, const TextLines& lines)
{
    if (name == "ascii") return PlyFormat::Text;
    if (name == "binary_little_endian") return PlyFormat::LittleEndian;
    if (name == "binary_big_endian") return PlyFormat::BigEndian;
    lines.fail("unknown PLY format '" + std::string(name) + "'");
}

void readProperty(const std::vector<std::string_view>& words, PlyHeader& header, const TextLines& lines)
{
    if (header.elements.empty()) lines.fail("a PLY property before any element");
    PlyProperty p;
    if (words.size() >= 5 && words[1] == "list") {
        p.countType = typeNamed(words[2], lines);
        p.type = typeNamed(words[3], lines);
        p.name = words[4];
    } else if (words.size() >= 3) {
        p.type = typeNamed(words[1], lines);
        p.name = words[2];
    } else {
        lines.fail("corrupt PLY property line (cut short?)");
    }
    header.elements.back().properties.push_back(p);
}

/// The header, up to "end_header" (at most 64 KiB of it).
PlyHeader readHeader(const std::string& bytes, const fs::path& path)
{
    const std::size_t end = bytes.find("end_header");
    const std::size_t lineEnd = end == std::string::npos ? end : bytes.find('\n', end);
    if (bytes.rfind("ply", 0) != 0) throw InputError(path.string() + ": not a PLY file (it must start with \"ply\")");
    if (lineEnd == std::string::npos || lineEnd > 65536 || bytes.find('\0') < lineEnd) {
        throw InputError(path.string() + ": truncated or corrupt PLY header (no end_header)");
    }
    PlyHeader header;
    TextLines lines(std::string_view(bytes).substr(0, end), path);
    bool formatSeen = false;
    for (const auto* words = &lines.next(); !words->empty(); words = &lines.next()) {
        const std::string_view key = (*words)[0];
        if (key == "format" && words->size() >= 2) {
            header.format = formatNamed((*words)[1], lines);
            formatSeen = true;
        } else if (key == "element") {
            if (words->size() < 3) lines.fail("corrupt PLY element line");
            const std::int64_t count = lines.integer((*words)[2], "an element count");
            if (count < 0 || count > std::int64_t(UINT32_MAX)) lines.fail("a PLY element count out of range");
            header.elements.push_back({std::string((*words)[1]), std::uint64_t(count), {}});
        } else if (key == "property") {
            readProperty(*words, header, lines);
        }
    }
    if (!formatSeen) throw InputError(path.string() + ": corrupt PLY header (no format line)");
    header.bodyOffset = lineEnd + 1;
    header.bodyLine = int(std::count(bytes.begin(), bytes.begin() + std::ptrdiff_t(lineEnd), '\n')) + 2;
    return header;
}

/// The body's numbers in order, from binary bytes or text lines (one element per line).
class PlyBody {
public:
    PlyBody(const std::string& bytes, const PlyHeader& header, const fs::path& path)
        : mBytes(bytes), mAt(header.bodyOffset), mFormat(header.format), mPath(path),
          mLines(std::string_view(bytes).substr(header.bodyOffset), path, '\0', header.bodyLine)
    {}

    /// Refuses `count` elements the rest of the file cannot hold, before anything is allocated.
    void requireRoomFor(const PlyElement& e)
    {
        const double left = double(mBytes.size() - std::min(mAt, mBytes.size()));
        const double least = mFormat == PlyFormat::Text ? 2.0 : double(e.minimalBytes());
        if (double(e.count) * least > left) {
            throw InputError(mPath.string() + ": truncated PLY: " + std::to_string(e.count) + " " + e.name +
                             " elements need at least " + formatNumber(double(e.count) * least) + " bytes; " +
                             formatNumber(left) + " remain");
        }
    }

    void beginElement(const PlyElement& e, std::uint64_t k)
    {
        mWhat = e.name + " " + std::to_string(k);
        if (mFormat != PlyFormat::Text) return;
        mWords = mLines.next();
        mWord = 0;
        if (mWords.empty()) throw InputError(mPath.string() + ": truncated PLY: " + mWhat + " is missing");
    }

    double next(PlyType type)
    {
        if (mFormat == PlyFormat::Text) {
            if (mWord >= mWords.size()) mLines.fail(mWhat + " is cut short");
            return mLines.number(mWords[mWord++], mWhat);
        }
        if (sizeOf(type) > mBytes.size() - std::min(mAt, mBytes.size())) {
            throw InputError(mPath.string() + ": truncated PLY: the file ends inside " + mWhat);
        }
        const char* at = mBytes.data() + mAt;
        mAt += sizeOf(type);
        const bool big = mFormat == PlyFormat::BigEndian;
        switch (type) {
        case PlyType::Int8: return readStored<std::int8_t>(at, big);
        case PlyType::UInt8: return readStored<std::uint8_t>(at, big);
        case PlyType::Int16: return readStored<std::int16_t>(at, big);
        case PlyType::UInt16: return readStored<std::uint16_t>(at, big);
        case PlyType::Int32: return readStored<std::int32_t>(at, big);
        case PlyType::UInt32: return readStored<std::uint32_t>(at, big);
        case PlyType::Float32: return readStored<float>(at, big);
        case PlyType::Float64: return readStored<double>(at, big);
        }
        return 0.0;
    }

    /// A list's length, refused when the rest of the file cannot hold its items.
    std::size_t listLength(const PlyProperty& p)
    {
        const double n = next(*p.countType);
        const double left = mFormat == PlyFormat::Text ? double(mWords.size() - mWord)
                                                       : double(mBytes.size() - mAt) / double(sizeOf(p.type));
        if (n < 0 || n != std::floor(n) || n > left) {
            throw InputError(mPath.string() + ": corrupt PLY: " + mWhat + " has a list of " + formatNumber(n) +
                             " items, more than the file holds");
        }
        return std::size_t(n);
    }

    /// A face corner: a whole number naming one of `vertices`.
    std::uint32_t vertexIndex(PlyType type, std::uint64_t vertices)
    {
        const double id = next(type);
        if (!(id >= 0 && id < double(vertices) && id == std::floor(id))) {
            throw InputError(mPath.string() + ": PLY " + mWhat + " names vertex " + formatNumber(id) + " of " +
                             std::to_string(vertices));
        }
        return std::uint32_t(id);
    }

private:
    const std::string& mBytes;
    std::size_t mAt;
    PlyFormat mFormat;
    const fs::path& mPath;
    TextLines mLines;
    std::vector<std::string_view> mWords;
    std::size_t mWord = 0;
    std::string mWhat;
};

bool isFaceIndexList(const PlyElement& e, const PlyProperty& p)
{
    return e.name == "face" && p.countType && (p.name == "vertex_indices" || p.name == "vertex_index");
}

void readElement(const PlyElement& e, std::uint64_t vertices, PlyBody& body, TriangleMesh& mesh)
{
    body.requireRoomFor(e);
    const bool isVertex = e.name == "vertex";
    if (isVertex) mesh.positions.resize(e.count);
    std::vector<std::uint32_t> ids;
    for (std::uint64_t k = 0; k < e.count; ++k) {
        body.beginElement(e, k);
        for (const PlyProperty& p : e.properties) {
            if (!p.countType) {
                const double value = body.next(p.type);
                if (isVertex && p.name.size() == 1 && p.name[0] >= 'x' && p.name[0] <= 'z') {
                    mesh.positions[k][std::size_t(p.name[0] - 'x')] = float(value);
                }
                continue;
            }
            const std::size_t n = body.listLength(p);
            if (!isFaceIndexList(e, p)) {
                for (std::size_t i = 0; i < n; ++i) body.next(p.type);
                continue;
            }
            ids.clear();
            for (std::size_t i = 0; i < n; ++i) ids.push_back(body.vertexIndex(p.type, vertices));
            fanPolygon(ids, mesh.triangles);
        }
    }
}

void requireCoordinates(const PlyHeader& header, const fs::path& path)
{
    for (const PlyElement& e : header.elements) {
        if (e.name != "vertex") continue;
        for (const char* axis : {"x", "y", "z"}) {
            const bool found = std::any_of(e.properties.begin(), e.properties.end(),
                                           [&](const PlyProperty& p) { return p.name == axis && !p.countType; });
            if (!found) throw InputError(path.string() + ": PLY vertices have no '" + axis + "' property");
        }
        return;
    }
    throw InputError(path.string() + ": the PLY file has no vertex element");
}

}  // namespace

TriangleMesh readPly(const fs::path& path)
{
    const std::string bytes = readWholeFile(path);
    const PlyHeader header = readHeader(bytes, path);
    requireCoordinates(header, path);
    PlyBody body(bytes, header, path);
    TriangleMesh mesh;
    for (const PlyElement& e : header.elements) readElement(e, header.countOf("vertex"), body, mesh);
    return mesh;
}

void writePly(const TriangleMesh& mesh, const fs::path& path, MeshFrame frame)
{
    const bool normals = mesh.normals.size() == mesh.positions.size() && !mesh.normals.empty();
    std::string bytes = "ply\nformat binary_little_endian 1.0\ncomment written by sculpt\ncomment " +
                        meshFrameTag(frame) + "\nelement vertex " + std::to_string(mesh.positions.size()) +
                        "\nproperty float x\nproperty float y\nproperty float z\n";
    if (normals) bytes += "property float nx\nproperty float ny\nproperty float nz\n";
    bytes += "element face " + std::to_string(mesh.triangles.size()) +
             "\nproperty list uchar int vertex_indices\nend_header\n";
    bytes.reserve(bytes.size() + mesh.positions.size() * (normals ? 24 : 12) + mesh.triangles.size() * 13);
    const float flip = frame == MeshFrame::Ras ? -1.0f : 1.0f;  // RAS: x and y negated
    const auto appendVector = [&](const std::array<float, 3>& v) {
        appendLittle(bytes, flip * v[0]);
        appendLittle(bytes, flip * v[1]);
        appendLittle(bytes, v[2]);
    };
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        appendVector(mesh.positions[v]);
        if (normals) appendVector(mesh.normals[v]);
    }
    for (const auto& t : mesh.triangles) {
        bytes.push_back(char(3));
        for (std::uint32_t id : t) appendLittle(bytes, std::int32_t(id));
    }
    std::ofstream out(path, std::ios::binary);
    if (!out.write(bytes.data(), std::streamsize(bytes.size())) || !out.flush()) {
        throw InputError(path.string() + ": cannot write the mesh (disk full or no permission?)");
    }
}

}  // namespace sculpt
