#include "sculpt/cli/commands.h"
#include "sculpt/cli/edit_document.h"
#include "sculpt/session/model_filter.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>

namespace sculpt::cli {

namespace {

struct OffsetOptions {
    DocumentInput input;
    std::string output;
    double distance = 0.0;
};

void runOffset(const OffsetOptions& o)
{
    const FieldImage field = editDocument(o.input, o.output, "offsetting", [&](FieldImage& f, const Progress& p) {
        f = applyFilter(std::move(f), {ModelFilter::Kind::Offset, 0, false, o.distance}, o.input.path, p);
    });
    std::cout << "wrote " << o.output << ": surface moved " << o.distance << " " << field.units()
              << " along its normal\n";
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
    cmd->callback([options] { runOffset(*options); });
}

}  // namespace sculpt::cli
