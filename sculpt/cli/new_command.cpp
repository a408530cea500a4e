// SPDX-License-Identifier: Apache-2.0
#include "core/base/atomic_file.h"
#include "core/base/errors.h"
#include "core/field/document_text.h"
#include "core/io/vdb_file.h"
#include "core/primitives/analytic_shapes.h"
#include "sculpt/cli/command_report.h"
#include "sculpt/cli/commands.h"
#include "sculpt/cli/mesh_output.h"

#include <CLI/CLI.hpp>

#include <memory>
#include <sstream>

namespace sculpt::cli {

namespace {

struct NewOptions {
    std::string shape = "sphere";
    double radius = 50.0;
    double minorRadius = 0.0;  // 0: radius / 3
    double voxelSize = 0.5;
    std::string units = FieldImage::kDefaultUnits;
    std::string output, mesh;
    RunOptions run;
};

void runNew(const NewOptions& o)
{
    AtomicFile::checkTarget(o.output);
    checkMeshOutput(o.mesh);
    if (const std::string problem = unitsProblem(o.units); !problem.empty())
        throw InputError("--units: the length unit cannot be: " + problem);
    const AnalyticSdf shape = startingShapeSdf(o.shape, o.radius, o.minorRadius);
    FieldImage field = rasterizeSdf(shape, o.voxelSize);
    field.setUnits(o.units);
    writeFieldImage(field, o.output);
    CommandReport report("new", o.run);
    report.wrote(o.output, "document");
    report["shape"] = o.shape;
    report["voxel_size"] = o.voxelSize;
    report["units"] = o.units;
    report["active_voxels"] = field.grid().activeVoxelCount();
    std::ostringstream line;
    line << "wrote " << o.output << ": " << shape.description << " " << o.units << ", voxel size " << o.voxelSize << " "
         << o.units << ", " << field.grid().activeVoxelCount() << " active voxels";
    report.say(line.str());
    writeMeshOutput(field, o.mesh, report);
    report.print();
}

}  // namespace

void addNewCommand(CLI::App& app)
{
    auto options = std::make_shared<NewOptions>();
    CLI::App* cmd = app.add_subcommand("new", "Create a document holding a starting shape, centred at the origin.\n"
                                              "The defaults give the clay ball a sculptor starts from.");
    cmd->footer(
        "Examples:\n  sculpt new -o ball.vdb\n  sculpt new --shape torus --radius 30 --voxel-size 0.25 -o ring.vdb");
    cmd->add_option("--shape", options->shape, "sphere, box or torus")
        ->check(CLI::IsMember({"sphere", "box", "torus"}))
        ->capture_default_str();
    cmd->add_option("--radius", options->radius, "sphere radius, box half side, or torus major radius (world units)")
        ->capture_default_str();
    cmd->add_option("--minor-radius", options->minorRadius, "torus tube radius (default: radius / 3)");
    cmd->add_option("--voxel-size", options->voxelSize,
                    "edge of a voxel in world units: smaller is finer and costs more memory")
        ->capture_default_str();
    cmd->add_option("--units", options->units, "length unit recorded in the document")->capture_default_str();
    cmd->add_option("-o,--output", options->output, "the .vdb document to write")->required();
    addMeshOutput(*cmd, options->mesh);
    addRunOptions(*cmd, options->run);
    cmd->callback([options] { runNew(*options); });
}

}  // namespace sculpt::cli
