#include "core/base/atomic_file.h"
#include "core/io/mesh_file.h"
#include "core/mesh/incremental_mesher.h"
#include "sculpt/cli/commands.h"
#include "sculpt/cli/document_input.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>

namespace sculpt::cli {

namespace {

struct MeshOptions {
    DocumentInput input;
    std::string output;
};

void runMesh(const MeshOptions& o)
{
    meshFormatOf(o.output);
    AtomicFile::checkTarget(o.output);
    const FieldImage field = readDocument(o.input).field;
    const TriangleMesh mesh = meshLevelSet(field);
    writeMesh(mesh, o.output);
    std::cout << "wrote " << o.output << ": " << mesh.positions.size() << " vertices, " << mesh.triangles.size()
              << " triangles\n";
}

}  // namespace

void addMeshCommand(CLI::App& app)
{
    auto options = std::make_shared<MeshOptions>();
    CLI::App* cmd =
        app.add_subcommand("mesh", "Export a document's surface as one welded, closed triangle mesh for printing\n"
                                   "or rendering. The format follows the output's extension: .ply (binary, with\n"
                                   "normals), .obj (text) or .stl (binary).");
    addDocumentInput(*cmd, options->input, "the .vdb document to mesh");
    cmd->add_option("-o,--output", options->output, "the mesh file to write")->required();
    cmd->callback([options] { runMesh(*options); });
}

}  // namespace sculpt::cli
