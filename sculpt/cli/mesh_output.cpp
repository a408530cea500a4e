// SPDX-License-Identifier: Apache-2.0
#include "sculpt/cli/mesh_output.h"

#include "core/base/atomic_file.h"
#include "core/io/mesh_file.h"
#include "core/mesh/incremental_mesher.h"
#include "sculpt/session/piece_meshes.h"

#include <CLI/CLI.hpp>

namespace sculpt::cli {

namespace {

void reportMeshes(const std::vector<WrittenMesh>& written, CommandReport& report)
{
    for (const WrittenMesh& mesh : written) {
        report.say(mesh.line());
        report.wrote(mesh.file.string(), "mesh");
        nlohmann::json& entry = report.lastOutput();
        if (!mesh.piece.empty()) entry["piece"] = mesh.piece;
        entry["vertices"] = mesh.vertices;
        entry["triangles"] = mesh.triangles;
    }
}

}  // namespace

void addMeshOutput(CLI::App& cmd, std::string& path)
{
    cmd.add_option("--mesh", path,
                   "also write the surface as .ply, .obj, .stl or .3mf (several pieces: a file per piece, or\n"
                   "one OBJ or 3MF of an object per piece)");
}

void checkMeshOutput(const std::string& path)
{
    if (path.empty()) return;
    meshFormatOf(path);
    AtomicFile::checkTarget(path);
}

void writeMeshOutput(const FieldImage& field, const std::string& path, CommandReport& report)
{
    if (path.empty()) return;
    reportMeshes(writePieceMeshes({{"", meshLevelSet(field), openvdb::Vec3f(0.8f), field.units()}}, path), report);
}

void writePiecesMeshes(const std::vector<Piece>& pieces, const std::string& path, CommandReport& report,
                       MeshFrame frame)
{
    if (path.empty()) return;
    checkMeshOutput(path);
    std::vector<PieceMesh> meshes;
    for (const Piece& piece : pieces)
        meshes.push_back(
            {piece.name, placedMesh(meshLevelSet(piece.field), piece.placement), piece.colour, piece.field.units()});
    reportMeshes(writePieceMeshes(meshes, path, frame), report);
}

}  // namespace sculpt::cli
