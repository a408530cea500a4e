#include "sculpt/session/piece_meshes.h"

#include "core/base/atomic_file.h"
#include "core/base/written_outputs.h"
#include "core/io/mesh_file.h"
#include "core/io/obj_file.h"

#include <cctype>

namespace sculpt {

namespace {

/// A piece's name as part of a file name: letters, digits, '-', '_' and '.' kept, others '_'.
std::string fileSafe(const std::string& name)
{
    std::string safe = name;
    for (char& c : safe)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
    return safe;
}

std::string wrote(const std::string& path, const std::string& what, const TriangleMesh& mesh)
{
    return "wrote " + path + what + ": " + std::to_string(mesh.positions.size()) + " vertices, " +
           std::to_string(mesh.triangles.size()) + " triangles";
}

}  // namespace

TriangleMesh placedMesh(TriangleMesh mesh, const openvdb::Mat4d& placement)
{
    if (placement == openvdb::Mat4d::identity()) return mesh;
    for (auto& p : mesh.positions) {
        const openvdb::Vec3d q = placement.transform(openvdb::Vec3d(p[0], p[1], p[2]));
        p = {float(q.x()), float(q.y()), float(q.z())};
    }
    for (auto& n : mesh.normals) {
        const openvdb::Vec3d m = placement.transform3x3(openvdb::Vec3d(n[0], n[1], n[2])).unit();
        n = {float(m.x()), float(m.y()), float(m.z())};
    }
    return mesh;
}

std::vector<std::string> writePieceMeshes(const std::vector<PieceMesh>& pieces, const std::filesystem::path& path,
                                          MeshFrame frame)
{
    meshFormatOf(path);
    AtomicFile::checkTarget(path);
    std::vector<std::string> lines;
    if (pieces.size() > 1 && meshFormatOf(path) == MeshFormat::Obj) {
        std::vector<ObjObject> objects;
        for (const PieceMesh& piece : pieces) objects.push_back({piece.name, &piece.mesh});
        writeObjObjects(objects, path, frame);
        for (const PieceMesh& piece : pieces)
            lines.push_back(wrote(path.string(), " object '" + piece.name + "'", piece.mesh));
        return lines;
    }
    std::vector<std::filesystem::path> files;
    for (const PieceMesh& piece : pieces) {
        files.push_back(pieces.size() == 1 ? path
                                           : path.parent_path() / (path.stem().string() + "-" + fileSafe(piece.name) +
                                                                   path.extension().string()));
        AtomicFile::checkTarget(files.back());
    }
    WrittenOutputs outputs;  // every piece's file, or (a write failing) none
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        writeMesh(pieces[i].mesh, outputs.file(files[i]), frame);
        lines.push_back(
            wrote(files[i].string(), pieces.size() > 1 ? " (piece '" + pieces[i].name + "')" : "", pieces[i].mesh));
    }
    outputs.keep();
    return lines;
}

}  // namespace sculpt
