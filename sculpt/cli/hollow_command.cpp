// SPDX-License-Identifier: Apache-2.0
#include "core/mesh/field_measures.h"
#include "sculpt/cli/command_report.h"
#include "sculpt/cli/commands.h"
#include "sculpt/cli/edit_document.h"
#include "sculpt/cli/mesh_output.h"
#include "sculpt/cli/number_checks.h"
#include "sculpt/session/model_filter.h"

#include <CLI/CLI.hpp>

#include <map>
#include <memory>
#include <sstream>

namespace sculpt::cli {

namespace {

struct HollowCommandOptions {
    DocumentInput input;
    std::string output, side = "inside", up = "z";
    ModelFilter filter{ModelFilter::Kind::Hollow};
    std::string mesh;
    RunOptions run;
};

const std::map<std::string, openvdb::Vec3d> kDirections{{"x", {1, 0, 0}},   {"y", {0, 1, 0}},   {"z", {0, 0, 1}},
                                                        {"-x", {-1, 0, 0}}, {"-y", {0, -1, 0}}, {"-z", {0, 0, -1}}};

void runHollow(HollowCommandOptions o)
{
    o.filter.hollow.side = shellSideFromName(o.side);
    o.filter.up = kDirections.at(o.up);
    checkMeshOutput(o.mesh);
    double before = 0.0;
    const FieldImage field = editDocument(o.input, o.output, "hollowing", [&](FieldImage& f, const Progress& p) {
        before = measureField(f).volume;
        f = applyFilter(std::move(f), o.filter, o.input.path, p);
    });
    const FieldMeasures after = measureField(field);
    CommandReport report("hollow", o.run);
    report.wrote(o.output, "document");
    report["thickness"] = o.filter.hollow.thicknessWorld;
    report["side"] = o.side;
    report["drain"] = o.filter.drain;
    report["units"] = field.units();
    report["volume_before"] = before;
    report["volume_after"] = after.volume;
    report["components"] = after.components;
    std::ostringstream line;
    line << "wrote " << o.output << ": a shell of " << o.filter.hollow.thicknessWorld << " " << field.units() << " ("
         << o.side << "), volume " << before << " -> " << after.volume << " " << field.units() << "^3, "
         << after.components << (after.components == 1 ? " surface" : " surfaces");
    report.say(line.str());
    writeMeshOutput(field, o.mesh, report);
    report.print();
}

}  // namespace

void addHollowCommand(CLI::App& app)
{
    auto options = std::make_shared<HollowCommandOptions>();
    CLI::App* cmd = app.add_subcommand(
        "hollow", "Make the solid a shell of a given wall thickness (less resin, lighter prints), with a\n"
                  "drain hole at the lowest point of each cavity for the print direction.");
    cmd->footer("Examples:\n  sculpt hollow figure.vdb --thickness 2 --drain -o shell.vdb");
    addDocumentInput(*cmd, options->input, "the .vdb document to hollow");
    cmd->add_option("--thickness", options->filter.hollow.thicknessWorld, "the wall's thickness, world units")
        ->check(positiveNumber())
        ->required();
    cmd->add_option("--side", options->side,
                    "inside: the wall within the surface (the outside stays); medial: centred on it;\n"
                    "outside: around it (the solid becomes the cavity)")
        ->check(CLI::IsMember({"inside", "medial", "outside"}))
        ->capture_default_str();
    cmd->add_option("--closing", options->filter.hollow.closingWorld,
                    "smooth the cavity's wall: no part of the cavity narrower than twice this (world units)")
        ->check(nonNegativeNumber())
        ->capture_default_str();
    options->filter.drain = false;
    cmd->add_flag("--drain", options->filter.drain,
                  "cut a drain hole through the wall under each cavity's lowest point");
    cmd->add_option("--drain-radius", options->filter.drainRadiusWorld, "the drain holes' radius, world units")
        ->check(positiveNumber())
        ->capture_default_str();
    cmd->add_option("--up", options->up, "the print direction (the build plate is below): x, y, z, -x, -y or -z")
        ->check(CLI::IsMember({"x", "y", "z", "-x", "-y", "-z"}))
        ->capture_default_str();
    cmd->add_option("-o,--output", options->output, "the .vdb document to write")->required();
    addMeshOutput(*cmd, options->mesh);
    addRunOptions(*cmd, options->run);
    cmd->callback([options] { runHollow(*options); });
}

}  // namespace sculpt::cli
