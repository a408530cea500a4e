// SPDX-License-Identifier: Apache-2.0
#include "core/io/obj_file.h"

#include "core/base/atomic_file.h"
#include "core/base/errors.h"
#include "core/io/text_lines.h"
#include "core/mesh/polygon_soup.h"

#include <cstdio>
#include <memory>

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

/// One object's lines; `first` and `firstNormal` are the 1-based numbers of its first vertex and
/// normal in the file.
/// One object's lines; `flip` negates x and y (the RAS frame).
void writeObject(std::FILE* file, const std::string& name, const TriangleMesh& mesh, std::size_t first,
                 std::size_t firstNormal, bool flip)
{
    if (!name.empty()) std::fprintf(file, "o %s\n", name.c_str());
    const float s = flip ? -1.0f : 1.0f;
    for (const auto& p : mesh.positions) std::fprintf(file, "v %.9g %.9g %.9g\n", s * p[0], s * p[1], p[2]);
    for (const auto& n : mesh.normals) std::fprintf(file, "vn %.6g %.6g %.6g\n", s * n[0], s * n[1], n[2]);
    const bool normals = !mesh.normals.empty();
    for (const auto& t : mesh.triangles) {
        const std::size_t a = t[0] + first, b = t[1] + first, c = t[2] + first;
        if (!normals) {
            std::fprintf(file, "f %zu %zu %zu\n", a, b, c);
            continue;
        }
        const std::size_t na = t[0] + firstNormal, nb = t[1] + firstNormal, nc = t[2] + firstNormal;
        std::fprintf(file, "f %zu//%zu %zu//%zu %zu//%zu\n", a, na, b, nb, c, nc);
    }
}

}  // namespace

void writeObjFile(const std::vector<ObjObject>& objects, const fs::path& path, MeshFrame frame)
{
    for (const ObjObject& object : objects)
        if (!object.mesh->finite()) throw InputError(path.string() + ": a vertex is not a finite number: not written");
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "w"), &std::fclose);
    if (!file) throw InputError(path.string() + ": cannot be written");
    std::fprintf(file.get(), "# written by sculpt\n# %s\n", meshFrameTag(frame).c_str());
    std::size_t first = 1, firstNormal = 1;
    for (const ObjObject& object : objects) {
        writeObject(file.get(), object.name, *object.mesh, first, firstNormal, frame == MeshFrame::Ras);
        first += object.mesh->positions.size();
        firstNormal += object.mesh->normals.size();
    }
    if (std::fflush(file.get()) != 0 || std::ferror(file.get()))
        throw InputError(path.string() + ": cannot be written (disk full?)");
}

void writeObjObjects(const std::vector<ObjObject>& objects, const fs::path& path, MeshFrame frame)
{
    AtomicFile out(path);
    writeObjFile(objects, out.temporaryPath(), frame);
    out.commit();
}

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
