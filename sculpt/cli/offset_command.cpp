// SPDX-License-Identifier: Apache-2.0
#include "core/mesh/field_measures.h"
#include "sculpt/cli/command_report.h"
#include "sculpt/cli/commands.h"
#include "sculpt/cli/edit_document.h"
#include "sculpt/cli/mesh_output.h"
#include "sculpt/session/model_filter.h"

#include <CLI/CLI.hpp>

#include <memory>
#include <sstream>

namespace sculpt::cli {

namespace {

struct OffsetOptions {
    DocumentInput input;
    std::string output;
    double distance = 0.0;
    std::string mesh;
    RunOptions run;
};

void runOffset(const OffsetOptions& o)
{
    checkMeshOutput(o.mesh);
    const FieldImage field = editDocument(o.input, o.output, "offsetting", [&](FieldImage& f, const Progress& p) {
        f = applyFilter(std::move(f), {ModelFilter::Kind::Offset, 0, false, o.distance}, o.input.path, p);
    });
    CommandReport report("offset", o.run);
    report.wrote(o.output, "document");
    report["distance"] = o.distance;
    report["units"] = field.units();
    report["volume_after"] = measureField(field).volume;
    std::ostringstream line;
    line << "wrote " << o.output << ": surface moved " << o.distance << " " << field.units() << " along its normal";
    report.say(line.str());
    writeMeshOutput(field, o.mesh, report);
    report.print();
}

}  // namespace

void addOffsetCommand(CLI::App& app)
{
    auto options = std::make_shared<OffsetOptions>();
    CLI::App* cmd =
        app.add_subcommand("offset", "Move the whole surface along its normal by a distance: positive grows\n"
                                     "(thickens), negative shrinks (thins). Cost grows with |distance| / voxel size.");
    cmd->footer("Examples:\n  sculpt offset head.vdb --distance 2 -o thicker.vdb");
    addDocumentInput(*cmd, options->input, "the .vdb document");
    addMaskInput(*cmd, options->input);
    cmd->add_option("--distance", options->distance, "offset in world units (> 0 grows)")->required();
    cmd->add_option("-o,--output", options->output, "the .vdb document to write")->required();
    addMeshOutput(*cmd, options->mesh);
    addRunOptions(*cmd, options->run);
    cmd->callback([options] { runOffset(*options); });
}

}  // namespace sculpt::cli
