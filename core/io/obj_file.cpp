#include "core/io/obj_file.h"

#include "core/base/errors.h"
#include "core/io/text_lines.h"
#include "core/mesh/polygon_soup.h"

namespace sculpt {

namespace fs = std::filesystem;

namespace {

/// The vertex a face corner "i[/t[/n]]" names, as a 0-based index into the vertices so far or
/// (positive indices may look ahead) into all of them, checked once all are read.
std::int64_t cornerVertex(std::string_view corner, std::int64_t verticesSoFar, const TextLines& lines)
{
    const std::int64_t i = lines.integer(corner.substr(0, corner.find('/')), "a face");
    if (i == 0) lines.fail("a face has vertex index 0 (OBJ counts from 1)");
    if (i > 0) return i - 1;
    if (-i > verticesSoFar) {
        lines.fail("a face has vertex index " + std::to_string(i) + " but only " + std::to_string(verticesSoFar) +
                   " vertices come before it");
    }
    return verticesSoFar + i;
}

}  // namespace

TriangleMesh readObj(const fs::path& path)
{
    const std::string text = readWholeFile(path);
    TextLines lines(text, path, '#');
    TriangleMesh mesh;
    std::int64_t largest = -1;  // the largest index a face names
    std::vector<std::uint32_t> ids;
    for (const auto* words = &lines.next(); !words->empty(); words = &lines.next()) {
        const std::string_view key = (*words)[0];
        if (key == "v") {
            if (words->size() < 4) lines.fail("a vertex needs x, y and z");
            std::array<float, 3> p;
            for (std::size_t a = 0; a < 3; ++a) p[a] = float(lines.number((*words)[a + 1], "a vertex"));
            mesh.positions.push_back(p);
        } else if (key == "f") {
            if (words->size() < 4) lines.fail("a face needs 3 or more vertices");
            ids.clear();
            for (std::size_t k = 1; k < words->size(); ++k) {
                const std::int64_t id = cornerVertex((*words)[k], std::int64_t(mesh.positions.size()), lines);
                if (id >= std::int64_t(UINT32_MAX)) lines.fail("a face has vertex index " + std::to_string(id + 1));
                largest = std::max(largest, id);
                ids.push_back(std::uint32_t(id));
            }
            fanPolygon(ids, mesh.triangles);
        }
    }
    if (largest >= std::int64_t(mesh.positions.size())) {
        throw InputError(path.string() + ": a face names vertex " + std::to_string(largest + 1) + " but the file has " +
                         std::to_string(mesh.positions.size()));
    }
    return mesh;
}

}  // namespace sculpt
