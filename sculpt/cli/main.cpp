// SPDX-License-Identifier: Apache-2.0
// The `sculpt` command-line program: every edit the UI can make, headless.
// Exit codes: 0 success, 2 bad input or usage, 1 internal error, 128 + N on signal N (130 Ctrl-C,
// 143 SIGTERM), with no temporary file left.

#include "core/base/errors.h"
#include "core/base/interrupt_cleanup.h"
#include "core/base/progress.h"
#include "core/io/vtk_logging.h"
#include "sculpt/cli/commands.h"
#include "sculpt/cli/shell_completion.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <sculpt_version.h>

namespace {

/// CLI11 reports a mistyped command as "a subcommand is required"; name it instead.
void rejectUnknownCommand(const CLI::App& app, int argc, char** argv)
{
    if (argc < 2 || argv[1][0] == '-') return;
    std::string known;
    for (const CLI::App* command : app.get_subcommands([](const CLI::App*) { return true; })) {
        if (command->get_name() == argv[1]) return;
        known += (known.empty() ? "" : ", ") + command->get_name();
    }
    throw sculpt::InputError("unknown command '" + std::string(argv[1]) + "' (commands: " + known + ")");
}

/// The flag that carries out what an error's remedy asks, as the end of its message.
const char* remedyFlag(sculpt::Remedy remedy)
{
    switch (remedy) {
    case sculpt::Remedy::None: return "";
    case sculpt::Remedy::CoarserVoxelSize: return " (a larger --voxel-size)";
    case sculpt::Remedy::FinerVoxelSize: return " (a smaller --voxel-size)";
    case sculpt::Remedy::AlignShapes: return " (--align)";
    case sculpt::Remedy::DescribeRawLayout: return " (--raw-dims, --raw-type, --raw-spacing)";
    case sculpt::Remedy::ChooseGrid: return " with --grid NAME";
    }
    return "";
}

}  // namespace

int main(int argc, char** argv)
{
    sculpt::quietVtkLogger();
    sculpt::exitCleanlyOnInterrupt("sculpt");
    CLI::App app{"sculpt: volumetric clay sculpting on sparse signed-distance grids.\n"
                 "Run 'sculpt COMMAND --help' for the options of a command."};
    app.name("sculpt");
    app.set_version_flag("--version", SCULPT_VERSION_TEXT("sculpt"));
    app.require_subcommand(1);
    sculpt::cli::addNewCommand(app);
    sculpt::cli::addInfoCommand(app);
    sculpt::cli::addMeshCommand(app);
    sculpt::cli::addSmoothCommand(app);
    sculpt::cli::addOffsetCommand(app);
    sculpt::cli::addMorphCommand(app);
    sculpt::cli::addBuildCommand(app);
    sculpt::cli::addApplyCommand(app);
    sculpt::cli::addImportCommand(app);
    sculpt::cli::addExportLabelsCommand(app);
    sculpt::cli::addHollowCommand(app);
    sculpt::cli::addIslandsCommand(app);
    sculpt::cli::addPiecesCommand(app);
    sculpt::cli::addRenderCommand(app);
    app.add_option("--completion", "print the completion script for bash, zsh or fish (installed with the program)")
        ->check(CLI::IsMember({"bash", "zsh", "fish"}))
        ->type_name("SHELL");
    if (argc < 2) {  // a bare call: the usage, not CLI11's "a subcommand is required"
        std::cerr << app.help();
        return 2;
    }
    try {
        if (argc == 3 && std::string(argv[1]) == "--completion") {  // no command needed
            std::cout << sculpt::cli::completionScript(app, argv[2]);
            return 0;
        }
        rejectUnknownCommand(app, argc, argv);
        app.parse(argc, argv);
        return 0;
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << "sculpt: " << e.what() << " (see 'sculpt --help')\n";
        return 2;
    } catch (const sculpt::Cancelled&) {
        std::cerr << "sculpt: cancelled\n";
        return 1;
    } catch (const sculpt::InputError& e) {
        std::cerr << "sculpt: " << e.what() << remedyFlag(e.remedy()) << "\n";
        return 2;
    } catch (const std::bad_alloc&) {
        std::cerr << "sculpt: out of memory\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "sculpt: internal error: " << e.what() << "\n";
        return 1;
    }
}
