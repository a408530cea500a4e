// SPDX-License-Identifier: Apache-2.0
#include "core/solids/islands.h"
#include "sculpt/cli/command_report.h"
#include "sculpt/cli/commands.h"
#include "sculpt/cli/edit_document.h"
#include "sculpt/cli/mesh_output.h"
#include "sculpt/cli/number_checks.h"
#include "sculpt/session/model_filter.h"

#include <CLI/CLI.hpp>

#include <memory>
#include <sstream>

namespace sculpt::cli {

namespace {

struct IslandsOptions {
    DocumentInput input;
    std::string output;
    double removeUnder = 0.0;
    std::string mesh;
    RunOptions run;
};

void runIslands(const IslandsOptions& o)
{
    checkMeshOutput(o.mesh);
    std::size_t removed = 0, found = 0;
    const FieldImage field = editDocument(o.input, o.output, "removing islands", [&](FieldImage& f, const Progress& p) {
        found = findIslands(f).size();
        ModelFilter filter{ModelFilter::Kind::RemoveIslands};
        filter.minIslandVolume = o.removeUnder;
        f = applyFilter(std::move(f), filter, o.input.path, p);
        removed = found - findIslands(f).size();
    });
    CommandReport report("islands", o.run);
    report.wrote(o.output, "document");
    report["islands_found"] = found;
    report["islands_removed"] = removed;
    report["remove_under"] = o.removeUnder;
    report["units"] = field.units();
    std::ostringstream line;
    line << "wrote " << o.output << ": " << removed << " of " << found << " islands were under " << o.removeUnder << " "
         << field.units() << "^3 and removed";
    report.say(line.str());
    writeMeshOutput(field, o.mesh, report);
    report.print();
}

}  // namespace

void addIslandsCommand(CLI::App& app)
{
    auto options = std::make_shared<IslandsOptions>();
    CLI::App* cmd = app.add_subcommand(
        "islands", "Remove the islands (disjoint solids: a scan's specks) smaller than a volume; the others keep\n"
                   "their voxels. `sculpt info` counts them (shells); `sculpt pieces --split` makes each a piece.");
    cmd->footer("Examples:\n  sculpt islands scan.vdb --remove-under 1 -o clean.vdb");
    addDocumentInput(*cmd, options->input, "the .vdb document");
    cmd->add_option("--remove-under", options->removeUnder,
                    "remove the islands of less volume than this (world units^3)")
        ->check(positiveNumber())
        ->required();
    cmd->add_option("-o,--output", options->output, "the .vdb document to write")->required();
    addMeshOutput(*cmd, options->mesh);
    addRunOptions(*cmd, options->run);
    cmd->callback([options] { runIslands(*options); });
}

}  // namespace sculpt::cli
