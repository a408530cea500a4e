// SPDX-License-Identifier: Apache-2.0
#include "sculpt/cli/command_report.h"
#include "sculpt/cli/commands.h"
#include "sculpt/cli/document_input.h"
#include "sculpt/cli/mesh_output.h"

#include <CLI/CLI.hpp>

#include <memory>

namespace sculpt::cli {

namespace {

struct MeshOptions {
    DocumentInput input;
    std::string output;
    bool ras = false;
    RunOptions run;
};

void runMesh(const MeshOptions& o)
{
    checkMeshOutput(o.output);
    CommandReport report("mesh", o.run);
    report["frame"] = o.ras ? "RAS" : "LPS";
    writePiecesMeshes(readPieces(o.input).pieces, o.output, report, o.ras ? MeshFrame::Ras : MeshFrame::Lps);
    report.print();
}

}  // namespace

void addMeshCommand(CLI::App& app)
{
    auto options = std::make_shared<MeshOptions>();
    CLI::App* cmd = app.add_subcommand(
        "mesh", "Export a document's surface as one welded, closed triangle mesh for printing\n"
                "or rendering. The format follows the output's extension: .ply (binary, with\n"
                "normals), .obj (text), .stl (binary) or .3mf (for slicers: the unit, an object per\n"
                "piece in its colour). A document of several pieces gives one OBJ or 3MF file of\n"
                "an object per piece, or a .ply or .stl file per piece named OUTPUT's stem, a\n"
                "dash and the piece's name; --piece NAME exports one.");
    cmd->footer(
        "Examples:\n  sculpt mesh head.vdb -o head.stl\n  sculpt mesh atlas.vdb -o atlas.obj   (an object per piece)");
    addDocumentInput(*cmd, options->input, "the .vdb document to mesh");
    cmd->add_option("-o,--output", options->output, "the mesh file to write")->required();
    cmd->add_flag("--ras", options->ras,
                  "write RAS coordinates (x to the patient's right, y to the front: FreeSurfer, nibabel)\n"
                  "instead of the document's LPS (x to the left, y to the back: DICOM, ITK, Slicer);\n"
                  "the header names the frame either way (SPACE=LPS or SPACE=RAS, as Slicer reads it)");
    addRunOptions(*cmd, options->run);
    cmd->callback([options] { runMesh(*options); });
}

}  // namespace sculpt::cli
