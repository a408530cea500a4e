// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file sculpt_app.h
/// @brief sculpt-ui: the window a sculptor works in. It composes the parts (the workspace and
///        its files, the view, the tools, the modes, the panels, the commands) and runs the loop:
///        every input, live or replayed, enters through handle() and is routed to the dialogs,
///        the tool, the open mode or the camera; every frame lands jobs, syncs the view and draws.
///        The parts see it through ToolHost and PanelHost only.

#include "ui/app/gui_context.h"
#include "ui/input/replay.h"
#include "ui/modes/mode_slot.h"
#include "ui/panels/panel_host.h"
#include "ui/scene/view_drag.h"
#include "ui/status/frame_log.h"
#include "ui/tools/tool_host.h"

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace sculpt::ui {

class Window;

struct AppOptions {
    std::filesystem::path document;                       ///< empty: the default clay ball
    std::string grid;                                     ///< the document's grid, in a file of several
    std::filesystem::path play, record;                   ///< event recordings
    std::filesystem::path screenshot;                     ///< after the opening view, or after the replay
    std::filesystem::path strokes;                        ///< a stroke script to replay into the document
    std::filesystem::path saveAs, exportMesh, strokeLog;  ///< written when the replay ends
    std::filesystem::path stateDir;                       ///< recovery files and recent files
    double autosaveSeconds = Autosave::kDefaultIntervalSeconds;
    std::size_t lodTriangles = 300000;  ///< far chunks coarse while moving or sculpting above this many
    /// A document opened or imported whose mesh exceeds this many triangles shows a coarse preview first.
    std::size_t previewTriangles = OpenPreview::kDefaultTriangleBudget;
    int chunkBlocks = 0;   ///< blocks per display chunk edge; 0: chosen from the model
    int slowFramesMs = 0;  ///< added to every frame (a slow machine, for tests)
    bool stay = false;     ///< keep the window open after a replay
};

class SculptApp final : private ToolHost, private PanelHost {
public:
    /// Runs in `window`; one that does not draw (HeadlessWindow) runs everything but the drawing.
    SculptApp(Window& window, AppOptions options);
    ~SculptApp();

    /// Runs until the user quits (or the replay ends). @return the exit status.
    int run();
    /// One input, live or replayed.
    void handle(const InputEvent& event);
    /// A command from a key, a menu or a button; if it cannot run now, the status bar says why.
    void execute(Command command) override;
    /// Every command, added by its owner: the keys, menus, tooltips and Help read it.
    const CommandRegistry& commands() const override { return mCommands; }

private:
    // The parts, as the tools and panels reach them.
    Workspace& workspace() override { return mWork; }
    DocumentFiles& files() override { return mFiles; }
    DocumentView& view() override { return mView; }
    BrushOptions& brush() override { return mBrush; }
    ToolBox& tools() override { return mTools; }
    Dialogs& dialogs() override { return mDialogs; }
    const StatusFigures& status() const override { return mStatus.figures(); }
    const PointerState& pointerState() const override { return mPointer; }
    FrameLog& frames() override { return mFrames; }
    double time() const override;

    /// The window's own commands: the brush's F drags and Quit.
    void addCommands();
    /// Another document is the workspace's: the view shows it, the measures start again.
    void showDocument(bool frameIt);

    /// One pass of the loop: input (live or replayed), autosave, a frame.
    void loopOnce(bool& replayDone);
    void frame();
    void drawPanels();
    /// The hover picked again if it went stale, and the brush cursor placed on it.
    void updateCursor();
    /// Nothing but frames' own state asks for a frame: no drag, no recent input, nothing pending.
    bool quiet() const;
    /// How long the loop may wait for input before its next frame (see inputWait's comment).
    double inputWait() const;
    /// What a replay's wait event waits for: a job, or a mode (a morph playing).
    bool holdsReplay() const;
    /// An exception no handler expected (out of memory, a bug, an OpenVDB error) reached the
    /// loop: the work is saved as a recovery copy, the error shown, and the window goes on.
    void recoverFromInternalError(const std::string& what);

    /// The command line's stroke script, one event per frame.
    void replayStrokes();
    /// What the command line asked for once the replay ends: save, export, the stroke log, a
    /// screenshot; then quit unless it should stay.
    void finishReplay();
    /// The screenshots and reports asked for, once the frame is drawn.
    void writeAsked();
    /// Appends the state as a JSON line to `path`, called `name` (if not ""): each part adds its own.
    void writeReport(const std::filesystem::path& path, const std::string& name);

    /// A file dropped on the window: opened (.vdb) or imported.
    void openDropped(const std::string& path);
    void routeMouse(const InputEvent& event);
    void routeKey(const InputEvent& event);
    /// While a dialog is open it takes every key: its answers are commands of Scope::Dialog.
    void routeDialogKey(const InputEvent& event);
    void pressButton(const InputEvent& event);
    void releaseButton(const InputEvent& event);
    void dragTo(const InputEvent& event, double dx, double dy);

    Window& mWindow;
    AppOptions mOptions;
    GuiContext mGui;  // before the parts whose panels it lays out, gone after them
    DocumentView mView;
    Workspace mWork;
    DocumentFiles mFiles;
    BrushOptions mBrush;
    ToolBox mTools;
    ModeSlot mModes;  // after the view: its modes draw into it
    CommandRegistry mCommands;
    Dialogs mDialogs;
    StatusTally mStatus;
    FrameLog mFrames;
    Replay mReplay;
    PointerState mPointer;
    ViewDrag mDrag;
    bool mQuit = false;
    int mExitStatus = 0;
};

}  // namespace sculpt::ui
