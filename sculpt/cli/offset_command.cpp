#include "commands.h"
#include "progress_bar.h"

#include <atomic_file.h>
#include <level_set_operations.h>
#include <vdb_file.h>

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>

namespace sculpt::cli {

namespace {

struct OffsetOptions {
    std::string input, output;
    double distance = 0.0;
};

void runOffset(const OffsetOptions& o)
{
    AtomicFile::checkTarget(o.output);
    FieldImage field = readFieldImage(o.input);
    {
        ProgressBar bar("offsetting");
        offset(field, o.distance, bar.callback());
    }
    writeFieldImage(field, o.output);
    std::cout << "wrote " << o.output << ": surface moved " << o.distance << " " << field.units()
              << " along its normal\n";
}

} // namespace

void addOffsetCommand(CLI::App& app)
{
    auto options = std::make_shared<OffsetOptions>();
    CLI::App* cmd = app.add_subcommand(
        "offset", "Move the whole surface along its normal by a distance: positive grows\n"
                  "(thickens), negative shrinks (thins). Cost grows with |distance| / voxel size.");
    cmd->add_option("input", options->input, "the .vdb document")->required();
    cmd->add_option("--distance", options->distance, "offset in world units (> 0 grows)")->required();
    cmd->add_option("-o,--output", options->output, "the .vdb document to write")->required();
    cmd->callback([options] { runOffset(*options); });
}

} // namespace sculpt::cli
