// SPDX-License-Identifier: Apache-2.0
#include "core/base/atomic_file.h"
#include "core/base/text_format.h"
#include "sculpt/cli/command_report.h"
#include "sculpt/cli/commands.h"
#include "sculpt/cli/document_input.h"
#include "sculpt/cli/mesh_output.h"
#include "sculpt/cli/number_checks.h"
#include "sculpt/cli/progress_bar.h"
#include "sculpt/session/document.h"
#include "sculpt/session/model_filter.h"
#include "sculpt/session/script_replay.h"

#include <CLI/CLI.hpp>

#include <memory>
#include <sstream>

namespace sculpt::cli {

namespace {

struct ApplyOptions {
    DocumentInput input;
    std::string script, output, mesh;
    RunOptions run;
};

void runApply(const ApplyOptions& o)
{
    checkMeshOutput(o.mesh);
    const StrokeScript script = readStrokeScript(o.script);  // every error before any work
    AtomicFile::checkTarget(o.output);
    VdbPieces file = readDocumentPieces(o.input);
    // Every piece, as the window holds them (piece edits replay too); no live meshes.
    Document document(std::move(file.pieces), {}, {}, PieceMeshes::None);
    ReplayReport done;
    {
        ProgressBar bar("replaying");
        done = replayScript(document, script, o.script, bar.callback());
    }
    for (const DocumentPiece& piece : document.pieces())
        refuseEmptyResult(piece.session->field(), o.input.path, "replaying");
    writeVdbPieces(document.piecesAsFiled(), o.output, file.companions);
    std::size_t historyBytes = 0;
    for (const DocumentPiece& piece : document.pieces()) historyBytes += piece.session->history().memoryBytes();
    CommandReport report("apply", o.run);
    report.wrote(o.output, "document");
    report["strokes"] = done.strokes;
    report["stamps"] = done.stamps;
    report["undos"] = done.undos;
    report["redos"] = done.redos;
    report["piece_edits"] = done.pieceEdits;
    report["pieces"] = document.pieces().size();
    report["history_bytes"] = historyBytes;
    std::ostringstream line;
    line << "wrote " << o.output << ": " << done.strokes << " strokes (" << done.stamps << " stamps), " << done.undos
         << " undo, " << done.redos << " redo";
    if (done.pieceEdits > 0)
        line << ", " << done.pieceEdits << " piece edits (" << document.pieces().size() << " pieces)";
    line << "; undo history " << formatBytes(historyBytes);
    report.say(line.str());
    writeMeshOutput(document.session().field(), o.mesh, report);
    report.print();
}

}  // namespace

void addApplyCommand(CLI::App& app)
{
    auto options = std::make_shared<ApplyOptions>();
    CLI::App* cmd = app.add_subcommand(
        "apply", "Replay a stroke script (brush strokes, mask and cut edits, drain holes, the pieces' edits,\n"
                 "undo and redo; see data/strokes.schema.json and data/strokes/) on a document, as\n"
                 "sculpt-ui's Save Strokes writes it. Replays are deterministic: the same input and\n"
                 "script give the same output bit for bit, whatever the thread count.");
    cmd->footer("Examples:\n  sculpt apply ball.vdb data/strokes/face.json -o face.vdb");
    addDocumentInput(*cmd, options->input, "the .vdb document to sculpt");
    addMaskInput(*cmd, options->input);
    cmd->add_option("script", options->script, "the stroke script (.json)")->required();
    cmd->add_option("-o,--output", options->output, "the .vdb document to write")->required();
    addMeshOutput(*cmd, options->mesh);
    addRunOptions(*cmd, options->run);
    cmd->callback([options] { runApply(*options); });
}

}  // namespace sculpt::cli
