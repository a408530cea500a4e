// SPDX-License-Identifier: Apache-2.0
#include "core/mesh/field_measures.h"
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

struct SmoothOptions {
    DocumentInput input;
    std::string output;
    int iterations = 10;
    bool keepVolume = false;
    std::string mesh;
    RunOptions run;
};

void runSmooth(const SmoothOptions& o)
{
    double before = 0.0;
    checkMeshOutput(o.mesh);
    const FieldImage field = editDocument(o.input, o.output, "smoothing", [&](FieldImage& f, const Progress& p) {
        before = measureField(f).volume;
        f = applyFilter(std::move(f), {ModelFilter::Kind::Smooth, o.iterations, o.keepVolume, 0.0}, o.input.path, p);
    });
    const double after = measureField(field).volume;
    CommandReport report("smooth", o.run);
    report.wrote(o.output, "document");
    report["iterations"] = o.iterations;
    report["volume_before"] = before;
    report["volume_after"] = after;
    report["units"] = field.units();
    std::ostringstream line;
    line << "wrote " << o.output << ": " << o.iterations << " smoothing iterations, volume " << before << " -> "
         << after << " " << field.units() << "^3";
    report.say(line.str());
    writeMeshOutput(field, o.mesh, report);
    report.print();
}

}  // namespace

void addSmoothCommand(CLI::App& app)
{
    auto options = std::make_shared<SmoothOptions>();
    CLI::App* cmd =
        app.add_subcommand("smooth", "Smooth the whole surface by mean-curvature flow: bumps and creases relax,\n"
                                     "small features vanish first. One iteration is one stable step (dt = h^2/6).");
    cmd->footer("Examples:\n  sculpt smooth brain.vdb --iterations 20 --keep-volume -o smooth.vdb");
    addDocumentInput(*cmd, options->input, "the .vdb document to smooth");
    addMaskInput(*cmd, options->input);
    cmd->add_option("--iterations", options->iterations, "number of smoothing steps")
        ->check(nonNegativeNumber())
        ->capture_default_str();
    cmd->add_flag("--keep-volume", options->keepVolume,
                  "hold the enclosed volume constant (otherwise smoothing shrinks the shape)");
    cmd->add_option("-o,--output", options->output, "the .vdb document to write")->required();
    addMeshOutput(*cmd, options->mesh);
    addRunOptions(*cmd, options->run);
    cmd->callback([options] { runSmooth(*options); });
}

}  // namespace sculpt::cli
