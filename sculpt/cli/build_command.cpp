// SPDX-License-Identifier: Apache-2.0
#include "core/base/atomic_file.h"
#include "core/base/errors.h"
#include "core/io/vdb_file.h"
#include "core/primitives/scene_file.h"
#include "sculpt/cli/command_report.h"
#include "sculpt/cli/commands.h"
#include "sculpt/cli/edit_document.h"
#include "sculpt/cli/mesh_output.h"
#include "sculpt/cli/number_checks.h"
#include "sculpt/session/scene_bake.h"

#include <CLI/CLI.hpp>

#include <memory>
#include <sstream>

namespace sculpt::cli {

namespace {

struct BuildOptions {
    std::string scene, base, output, mesh;
    double voxelSize = 0.0;
    RunOptions run;
};

void runBuild(const BuildOptions& o)
{
    AtomicFile::checkTarget(o.output);
    checkMeshOutput(o.mesh);
    const Scene scene = readScene(o.scene);
    const FieldImage result =
        o.base.empty() ? bakeScene(scene, o.voxelSize > 0.0 ? o.voxelSize : scene.voxelSize.value_or(0.5), o.scene)
                       : bakeScene(readFieldImage(o.base), scene, o.scene, o.base);
    writeFieldImage(result, o.output);
    CommandReport report("build", o.run);
    report.wrote(o.output, "document");
    report["primitives"] = scene.primitives.primitives().size();
    report["active_voxels"] = result.grid().activeVoxelCount();
    report["voxel_size"] = result.voxelSize();
    std::ostringstream line;
    line << "wrote " << o.output << ": " << scene.primitives.primitives().size() << " primitives"
         << (o.base.empty() ? "" : " combined into " + o.base) << ", " << result.grid().activeVoxelCount()
         << " active voxels";
    report.say(line.str());
    writeMeshOutput(result, o.mesh, report);
    report.print();
}

}  // namespace

void addBuildCommand(CLI::App& app)
{
    auto options = std::make_shared<BuildOptions>();
    CLI::App* cmd =
        app.add_subcommand("build", "Bake a scene of implicit primitives (skeletons with field kernels, blended, see\n"
                                    "data/scene.schema.json) into a document, alone or combined into a base document\n"
                                    "by the scene's operation (union, difference, intersection, replace).");
    cmd->footer("Examples:\n  sculpt build data/scenes/snowman.json -o snowman.vdb\n  sculpt build ear.json --into "
                "head.vdb -o head-with-ear.vdb");
    cmd->add_option("scene", options->scene, "the scene .json file")->required();
    cmd->add_option("--voxel-size", options->voxelSize,
                    "voxel size without --into (default: the scene's voxel_size, else 0.5)")
        ->check(positiveNumber());
    cmd->add_option("--into", options->base, "base .vdb document to combine the scene into");
    cmd->add_option("-o,--output", options->output, "the .vdb document to write")->required();
    addMeshOutput(*cmd, options->mesh);
    addRunOptions(*cmd, options->run);
    cmd->callback([options] { runBuild(*options); });
}

}  // namespace sculpt::cli
