// SPDX-License-Identifier: Apache-2.0
#include "core/io/stl_file.h"

#include "core/base/errors.h"
#include "core/base/text_format.h"
#include "core/io/byte_order.h"
#include "core/io/text_lines.h"

namespace sculpt {

namespace fs = std::filesystem;

namespace {

template <typename T>
T readLittle(const char* at)
{
    return readStored<T>(at, /*bigEndian=*/false);
}

/// Binary when the size matches the count exactly (some binary headers start with "solid"),
/// else text when it starts with "solid".
bool isBinary(const std::string& bytes)
{
    if (bytes.size() >= 84 && bytes.size() == 84 + 50 * std::size_t(readLittle<std::uint32_t>(bytes.data() + 80))) {
        return true;
    }
    return bytes.rfind("solid", 0) != 0;
}

TriangleMesh readText(const std::string& bytes, const fs::path& path)
{
    TextLines lines(bytes, path);
    TriangleMesh mesh;
    for (const auto* words = &lines.next(); !words->empty(); words = &lines.next()) {
        if ((*words)[0] != "vertex") continue;
        if (words->size() < 4) lines.fail("a vertex needs x, y and z");
        std::array<float, 3> p;
        for (std::size_t a = 0; a < 3; ++a) p[a] = float(lines.number((*words)[a + 1], "a vertex"));
        mesh.positions.push_back(p);
    }
    if (mesh.positions.size() % 3 != 0) {
        throw InputError(path.string() + ": corrupt text STL (" + std::to_string(mesh.positions.size()) +
                         " vertices: not three per facet)");
    }
    for (std::uint32_t v = 0; v < mesh.positions.size(); v += 3) mesh.triangles.push_back({v, v + 1, v + 2});
    return mesh;
}

TriangleMesh readBinary(const std::string& bytes, const fs::path& path)
{
    if (bytes.size() < 84) {
        throw InputError(path.string() + ": too short for a binary STL (" + std::to_string(bytes.size()) + " bytes)");
    }
    const auto count = readLittle<std::uint32_t>(bytes.data() + 80);
    const double expected = 84.0 + 50.0 * double(count);
    if (double(bytes.size()) < expected) {
        throw InputError(path.string() + ": truncated binary STL: it declares " + std::to_string(count) +
                         " triangles (" + formatNumber(expected) + " bytes) but holds " + std::to_string(bytes.size()) +
                         " bytes");
    }
    TriangleMesh mesh;
    mesh.positions.resize(3 * std::size_t(count));
    mesh.triangles.resize(count);
    for (std::uint32_t t = 0; t < count; ++t) {
        const char* corners = bytes.data() + 84 + 50 * std::size_t(t) + 12;  // after the facet normal
        for (std::uint32_t c = 0; c < 3; ++c) {
            for (std::size_t a = 0; a < 3; ++a)
                mesh.positions[3 * t + c][a] = readLittle<float>(corners + 12 * c + 4 * a);
        }
        mesh.triangles[t] = {3 * t, 3 * t + 1, 3 * t + 2};
    }
    return mesh;
}

}  // namespace

TriangleMesh readStl(const fs::path& path)
{
    const std::string bytes = readWholeFile(path);
    return isBinary(bytes) ? readBinary(bytes, path) : readText(bytes, path);
}

}  // namespace sculpt
