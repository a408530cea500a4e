// SPDX-License-Identifier: Apache-2.0
#include "core/io/off_file.h"

#include "core/base/errors.h"
#include "core/io/text_lines.h"
#include "core/mesh/polygon_soup.h"

namespace sculpt {

namespace fs = std::filesystem;

namespace {

void checkKeyword(std::string_view word, const fs::path& path)
{
    std::string_view rest = word;
    for (std::string_view prefix : {"ST", "C", "N"}) {
        if (rest.substr(0, prefix.size()) == prefix) rest.remove_prefix(prefix.size());
    }
    if (rest == "OFF") return;
    if (rest == "4OFF" || rest == "nOFF") {
        throw InputError(path.string() + ": " + std::string(word) + " holds points of more than 3 dimensions");
    }
    throw InputError(path.string() + ": not an OFF file (it must start with OFF, COFF, NOFF or STOFF)");
}

}  // namespace

TriangleMesh readOff(const fs::path& path)
{
    const std::string text = readWholeFile(path);
    TextLines lines(text, path, '#');
    std::vector<std::string_view> header = lines.next();
    if (header.empty()) throw InputError(path.string() + ": empty OFF file");
    checkKeyword(header[0], path);
    if (header.size() > 1 && header[1] == "BINARY") throw InputError(path.string() + ": binary OFF is not supported");
    header.erase(header.begin());
    if (header.empty()) header = lines.next();  // the counts on the next line, as usual
    if (header.size() < 2) lines.fail("corrupt OFF header (expected vertex and face counts)");
    const std::int64_t vertices = lines.integer(header[0], "the vertex count");
    const std::int64_t faces = lines.integer(header[1], "the face count");
    // Each vertex and face takes at least 6 characters of text: refuse counts the file cannot hold.
    const auto size = std::int64_t(text.size());
    if (vertices < 0 || faces < 0 || vertices > size / 6 || faces > size / 6) {
        lines.fail("the header claims " + std::string(header[0]) + " vertices and " + std::string(header[1]) +
                   " faces, which the file cannot hold");
    }
    TriangleMesh mesh;
    mesh.positions.resize(std::size_t(vertices));
    for (std::int64_t v = 0; v < vertices; ++v) {
        const auto& words = lines.next();
        const std::string what = "vertex " + std::to_string(v);
        if (words.size() < 3) lines.fail("truncated vertex list (" + what + ")");
        for (std::size_t a = 0; a < 3; ++a) mesh.positions[std::size_t(v)][a] = float(lines.number(words[a], what));
    }
    std::vector<std::uint32_t> ids;
    for (std::int64_t f = 0; f < faces; ++f) {
        const auto& words = lines.next();
        const std::string what = "face " + std::to_string(f);
        if (words.empty()) lines.fail("truncated face list (" + what + ")");
        const std::int64_t n = lines.integer(words[0], what);
        if (n < 3 || std::int64_t(words.size()) < n + 1) lines.fail(what + " needs 3 or more vertex indices");
        ids.clear();
        for (std::int64_t k = 1; k <= n; ++k) {
            const std::int64_t id = lines.integer(words[std::size_t(k)], what);
            if (id < 0 || id >= vertices) {
                lines.fail(what + " has vertex index " + std::to_string(id) + ", outside 0.." +
                           std::to_string(vertices - 1));
            }
            ids.push_back(std::uint32_t(id));
        }
        fanPolygon(ids, mesh.triangles);
    }
    return mesh;
}

}  // namespace sculpt
