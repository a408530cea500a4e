#include "core/base/text_format.h"
#include "sculpt/cli/commands.h"
#include "sculpt/cli/edit_document.h"
#include "sculpt/cli/mesh_output.h"
#include "sculpt/cli/number_checks.h"
#include "sculpt/session/stroke_script.h"

#include <CLI/CLI.hpp>
#include <tbb/global_control.h>

#include <iostream>
#include <memory>
#include <optional>

namespace sculpt::cli {

namespace {

struct ApplyOptions {
    DocumentInput input;
    std::string script, output, mesh;
    int threads = 0;
};

void runApply(const ApplyOptions& o)
{
    std::optional<tbb::global_control> threadLimit;
    if (o.threads > 0) threadLimit.emplace(tbb::global_control::max_allowed_parallelism, size_t(o.threads));
    checkMeshOutput(o.mesh);
    const StrokeScript script = readStrokeScript(o.script);  // every error before any work
    ReplayReport done;
    std::size_t historyBytes = 0;
    const FieldImage result = editDocument(o.input, o.output, "replaying", [&](FieldImage& field, const Progress& p) {
        SculptSession session(std::move(field));
        done = replayScript(session, script, o.script, p);
        historyBytes = session.history().memoryBytes();
        field = session.takeField();
    });
    std::cout << "wrote " << o.output << ": " << done.strokes << " strokes (" << done.stamps << " stamps), "
              << done.undos << " undo, " << done.redos << " redo; undo history " << formatBytes(historyBytes) << "\n";
    writeMeshOutput(result, o.mesh);
}

}  // namespace

void addApplyCommand(CLI::App& app)
{
    auto options = std::make_shared<ApplyOptions>();
    CLI::App* cmd = app.add_subcommand(
        "apply", "Replay a stroke script (brush strokes, undo and redo; see data/strokes.schema.json\n"
                 "and data/strokes/) on a document. Replays are deterministic: the same input and\n"
                 "script give the same output bit for bit, whatever the thread count.");
    addDocumentInput(*cmd, options->input, "the .vdb document to sculpt");
    addMaskInput(*cmd, options->input);
    cmd->add_option("script", options->script, "the stroke script (.json)")->required();
    cmd->add_option("-o,--output", options->output, "the .vdb document to write")->required();
    cmd->add_option("--mesh", options->mesh, "also write the surface as .ply, .obj or .stl");
    cmd->add_option("--threads", options->threads, "worker threads (default: all cores)")->check(positiveNumber());
    cmd->callback([options] { runApply(*options); });
}

}  // namespace sculpt::cli
