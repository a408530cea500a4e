// SPDX-License-Identifier: Apache-2.0
/// sculpt-ui: the sculpting window. See --help and the README.

#include "core/base/errors.h"
#include "core/io/vtk_logging.h"
#include "ui/app/sculpt_app.h"
#include "ui/app/window_icon.h"
#include "ui/window/app_window.h"
#include "ui/window/headless_window.h"

#include <CLI/CLI.hpp>
#include <vtkAutoInit.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>

#include <cstdlib>
#include <iostream>
#include <memory>
#include <sculpt_version.h>

// Without these VTK builds no OpenGL objects: every frame would be one solid colour.
VTK_MODULE_INIT(vtkRenderingOpenGL2);

namespace {

bool parseSize(const std::string& text, int& width, int& height)
{
    return std::sscanf(text.c_str(), "%dx%d", &width, &height) == 2 && width >= 64 && height >= 64 && width <= 8192 &&
           height <= 8192;
}

/// VTK's chatter (render warnings) dropped.
class QuietVtkOutput : public vtkOutputWindow {
public:
    static QuietVtkOutput* New();
    void DisplayText(const char*) override {}
    void DisplayErrorText(const char*) override {}
    void DisplayWarningText(const char*) override {}
    void DisplayGenericWarningText(const char*) override {}
    void DisplayDebugText(const char*) override {}
};
vtkStandardNewMacro(QuietVtkOutput);

}  // namespace

int main(int argc, char** argv)
{
    using namespace sculpt;
    ui::AppOptions options;
    options.stateDir = ui::Autosave::stateDirectory();
    std::string size = "1280x800";
    CLI::App cli("sculpt-ui: sculpt virtual clay. Opens FILE (a .vdb document), or a new clay ball.\n"
                 "Left drag sculpts, middle/right drag orbits, wheel zooms; F1 lists every key.\n"
                 "For tests and demos it replays recorded input (--play) without a person.");
    cli.name("sculpt-ui");
    cli.set_version_flag("--version", SCULPT_VERSION_TEXT("sculpt-ui"));
    cli.add_option("file", options.document, "the .vdb document to open (default: a new clay ball)");
    cli.add_option("--grid", options.grid,
                   "the grid to sculpt when the file holds several level sets (default: the one named\n"
                   "'surface', else the only one; File > Open asks). The others are kept.");
    cli.add_option("--play", options.play, "replay input events recorded with --record (data/ui-events.schema.json)")
        ->check(CLI::ExistingFile);
    cli.add_option("--record", options.record, "write every input event to this file at exit");
    cli.add_option(
        "--screenshot", options.screenshot,
        "write the composed window as PNG: alone, of the opening view; with --play or --strokes, at the end");
    cli.add_option("--strokes", options.strokes, "replay a `sculpt apply` stroke script into the document, on screen")
        ->check(CLI::ExistingFile);
    cli.add_option("--save-as", options.saveAs, "after --play or --strokes, save the document here (.vdb)");
    cli.add_option("--export", options.exportMesh,
                   "after --play or --strokes, export the mesh here (.ply .obj .stl .3mf)");
    cli.add_option("--stroke-log", options.strokeLog,
                   "after --play or --strokes, save the session's strokes as a stroke script");
    cli.add_flag("--stay", options.stay, "keep the window open after a replay");
    bool headless = false;
    cli.add_flag("--headless", headless,
                 "no window and no display: a replay (--play or --strokes) runs whole and writes what it is\n"
                 "asked to (--save-as, --export, --stroke-log, reports); nothing is drawn, so no --screenshot");
    cli.add_option("--size", size, "window size, WIDTHxHEIGHT")->capture_default_str();
    cli.add_option("--autosave-seconds", options.autosaveSeconds, "autosave interval while there are unsaved changes")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    cli.add_option("--state-dir", options.stateDir, "where recovery files and recent files live")
        ->capture_default_str();
    cli.add_option("--lod-triangles", options.lodTriangles,
                   "above this many triangles, parts of the model under two pixels per voxel are drawn coarse "
                   "while the camera moves or a stroke runs (full detail near the brush and when still)")
        ->capture_default_str();
    cli.add_option("--preview-triangles", options.previewTriangles,
                   "a document opened or imported whose mesh would exceed this many triangles shows a coarse "
                   "preview of about as many first, then fills in full detail")
        ->capture_default_str()
        ->check(CLI::PositiveNumber);
    cli.add_option("--display-chunk", options.chunkBlocks,
                   "blocks per edge of a display chunk (one draw call each); 0 chooses from the model's size")
        ->capture_default_str()
        ->check(CLI::Range(0, 32));
    cli.add_option("--slow-frames", options.slowFramesMs,
                   "add this many milliseconds to every frame, as a slow machine would (input then arrives "
                   "faster than frames: strokes must still follow every event)")
        ->check(CLI::Range(0, 5000));
    CLI11_PARSE(cli, argc, argv);

    int width = 0, height = 0;
    if (!parseSize(size, width, height)) {
        std::cerr << "sculpt-ui: --size " << size << ": expected WIDTHxHEIGHT, 64 to 8192 pixels each\n";
        return 2;
    }
    if (headless && (options.play.empty() == options.strokes.empty() || !options.screenshot.empty() || options.stay)) {
        std::cerr << "sculpt-ui: --headless replays exactly one of --play or --strokes, without --screenshot or "
                     "--stay (nothing is drawn, no one is there)\n";
        return 2;
    }
    // VTK's own chatter stays out of the terminal. Not GlobalWarningDisplayOff(): that would also
    // silence the readers' errors, which are caught per call and shown in the window.
    vtkOutputWindow::SetInstance(vtkNew<QuietVtkOutput>());
    quietVtkLogger();
    try {
        std::unique_ptr<ui::Window> window;
        if (headless) window = std::make_unique<ui::HeadlessWindow>(width, height);
        else {
            auto shown = std::make_unique<ui::AppWindow>(width, height, "Sculpt");
            shown->setIcon(ui::applicationIcon());
            window = std::move(shown);
        }
        ui::SculptApp app(*window, options);
        return app.run();
    } catch (const InputError& e) {
        std::cerr << "sculpt-ui: " << e.what() << "\n";
        return 2;
    } catch (const ui::WindowUnavailable& e) {  // exit 2: scripts/demo.sh then runs it headless
        const char* display = std::getenv("DISPLAY");
        std::cerr << "sculpt-ui: " << e.what()
                  << ((display && *display) ? " (DISPLAY=" + std::string(display) + ")"
                                            : std::string(" (DISPLAY is not set)"))
                  << "; run it under xvfb-run -a, see the README\n";
        return 2;
    } catch (const std::exception& e) {  // an internal error
        std::cerr << "sculpt-ui: internal error: " << e.what() << "\n";
        return 1;
    }
}
