#include "sculpt/cli/mesh_output.h"

#include "core/base/atomic_file.h"
#include "core/io/mesh_file.h"
#include "core/mesh/incremental_mesher.h"
#include "sculpt/session/piece_meshes.h"

#include <iostream>

namespace sculpt::cli {

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

void writePiecesMeshes(const std::vector<Piece>& pieces, const std::string& path, MeshFrame frame)
{
    checkMeshOutput(path);
    std::vector<PieceMesh> meshes;
    for (const Piece& piece : pieces)
        meshes.push_back({piece.name, placedMesh(meshLevelSet(piece.field), piece.placement)});
    for (const std::string& line : writePieceMeshes(meshes, path, frame)) std::cout << line << "\n";
}

}  // namespace sculpt::cli
