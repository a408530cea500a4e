// SPDX-License-Identifier: Apache-2.0
#include "sculpt/session/piece_meshes.h"

#include "core/base/atomic_file.h"
#include "core/base/written_outputs.h"
#include "core/io/mesh_file.h"
#include "core/io/obj_file.h"
#include "core/io/threemf_file.h"

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

}  // namespace

std::vector<std::string> linesOf(const std::vector<WrittenMesh>& written)
{
    std::vector<std::string> lines;
    for (const WrittenMesh& mesh : written) lines.push_back(mesh.line());
    return lines;
}

std::string WrittenMesh::line() const
{
    const std::string what = piece.empty() ? "" : sharedFile ? " object '" + piece + "'" : " (piece '" + piece + "')";
    return "wrote " + file.string() + what + ": " + std::to_string(vertices) + " vertices, " +
           std::to_string(triangles) + " triangles";
}

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

std::vector<WrittenMesh> writePieceMeshes(const std::vector<PieceMesh>& pieces, const std::filesystem::path& path,
                                          MeshFrame frame)
{
    meshFormatOf(path);
    AtomicFile::checkTarget(path);
    std::vector<WrittenMesh> written;
    if (meshFormatOf(path) == MeshFormat::ThreeMf) {
        std::vector<ThreeMfObject> objects;
        for (const PieceMesh& piece : pieces) objects.push_back({piece.name, &piece.mesh, piece.colour});
        writeThreeMf(objects, path, pieces.front().units, frame);
        for (const PieceMesh& piece : pieces)
            written.push_back({path, pieces.size() > 1 ? piece.name : "", piece.mesh.positions.size(),
                               piece.mesh.triangles.size(), true});
        return written;
    }
    if (pieces.size() > 1 && meshFormatOf(path) == MeshFormat::Obj) {
        std::vector<ObjObject> objects;
        for (const PieceMesh& piece : pieces) objects.push_back({piece.name, &piece.mesh});
        writeObjObjects(objects, path, frame);
        for (const PieceMesh& piece : pieces)
            written.push_back({path, piece.name, piece.mesh.positions.size(), piece.mesh.triangles.size(), true});
        return written;
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
        written.push_back({files[i], pieces.size() > 1 ? pieces[i].name : "", pieces[i].mesh.positions.size(),
                           pieces[i].mesh.triangles.size(), false});
    }
    outputs.keep();
    return written;
}

}  // namespace sculpt
