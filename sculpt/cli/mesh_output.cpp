#include "sculpt/cli/mesh_output.h"

#include "core/base/atomic_file.h"
#include "core/io/mesh_file.h"
#include "core/io/obj_file.h"
#include "core/mesh/incremental_mesher.h"

#include <cctype>
#include <filesystem>
#include <iostream>

namespace sculpt::cli {

namespace {

/// A piece's name as part of a file name: letters, digits, '-', '_' and '.' kept, others '_'.
std::string fileSafe(const std::string& name)
{
    std::string safe = name;
    for (char& c : safe)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
    return safe;
}

void report(const std::string& path, const std::string& what, const TriangleMesh& mesh)
{
    std::cout << "wrote " << path << what << ": " << mesh.positions.size() << " vertices, " << mesh.triangles.size()
              << " triangles\n";
}

}  // namespace

void checkMeshOutput(const std::string& path)
{
    if (path.empty()) return;
    meshFormatOf(path);
    AtomicFile::checkTarget(path);
}

void writeMeshOutput(const FieldImage& field, const std::string& path)
{
    if (path.empty()) return;
    const TriangleMesh mesh = meshLevelSet(field);
    writeMesh(mesh, path);
    std::cout << "wrote " << path << ": " << mesh.triangles.size() << " triangles\n";
}

void writePiecesMeshes(const std::vector<Piece>& pieces, const std::string& path)
{
    checkMeshOutput(path);
    if (pieces.size() > 1 && meshFormatOf(path) == MeshFormat::Obj) {
        std::vector<std::pair<std::string, TriangleMesh>> objects;
        for (const Piece& piece : pieces) objects.emplace_back(piece.name, meshLevelSet(piece.field));
        writeObjObjects(objects, path);
        for (const auto& [name, mesh] : objects) report(path, " object '" + name + "'", mesh);
        return;
    }
    std::vector<std::string> files;
    const std::filesystem::path target(path);
    for (const Piece& piece : pieces) {
        const std::filesystem::path file =
            pieces.size() == 1 ? target
                               : target.parent_path() / (target.stem().string() + "-" + fileSafe(piece.name) +
                                                         target.extension().string());
        files.push_back(file.string());
        AtomicFile::checkTarget(file);
    }
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        const TriangleMesh mesh = meshLevelSet(pieces[i].field);
        writeMesh(mesh, files[i]);
        report(files[i], pieces.size() > 1 ? " (piece '" + pieces[i].name + "')" : "", mesh);
    }
}

}  // namespace sculpt::cli
