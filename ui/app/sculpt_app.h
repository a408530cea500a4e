#pragma once
/// @file sculpt_app.h
/// @brief sculpt-ui: the window a sculptor works in. Owns the document, the 3D view and the
///        panels; every input, live or replayed, enters through handle().

#include "core/motion/morph.h"
#include "core/primitives/skeleton.h"
#include "sculpt/session/document.h"
#include "sculpt/session/model_filter.h"
#include "ui/app/gui_context.h"
#include "ui/commands/command_registry.h"
#include "ui/document/autosave.h"
#include "ui/document/file_listing.h"
#include "ui/document/open_preview.h"
#include "ui/document/recent_files.h"
#include "ui/input/event_player.h"
#include "ui/input/pointer_state.h"
#include "ui/jobs/job_runner.h"
#include "ui/modes/mode.h"
#include "ui/modes/mode_host.h"
#include "ui/scene/document_view.h"
#include "ui/sculpting/stroke_controller.h"
#include "ui/status/status_tally.h"
#include "ui/tools/tool_box.h"
#include "ui/tools/tool_host.h"

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace sculpt::ui {

class Window;
class PrimitivesMode;

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

/// The dialogs ImGui shows; at most one prompt at a time.
struct Dialogs {
    enum class Prompt {
        None,
        New,
        Open,
        SaveAs,
        ExportMesh,
        SaveStrokes,
        SmoothModel,
        OffsetModel,
        HollowModel,
        RemoveIslands,
        Morph,
        MorphExport,
        Target,
        Import,
        LoadScene,
        SaveScene
    };
    Prompt prompt = Prompt::None;
    std::string path;          ///< the prompt's text field
    DirectoryListing listing;  ///< what the file chooser under it shows
    double listedAt = -1.0;    ///< when that was read (ImGui's clock)
    NewShape newShape;
    ModelFilter filter;                             ///< the Smooth/Offset Model prompts' settings
    MorphOptions morph;                             ///< the Morph To prompt's settings (target: path)
    bool morphTracked = false;                      ///< ... and whether it tracks a mesh along
    std::optional<Command> afterUnsaved;            ///< asking "save changes?" before this command
    std::optional<std::filesystem::path> recovery;  ///< offering to recover this file
    /// Asking which level set of a file to open (it holds several, none named "surface").
    struct GridChoice {
        std::filesystem::path file;
        std::vector<std::string> grids;
    };
    std::optional<GridChoice> gridChoice;
    /// True if the open prompt can be confirmed (one asking for a path needs one).
    bool confirmable() const;
    /// The Pieces panel's name field (of piece pieceNameOf, named pieceNameSeen then).
    std::string pieceName, pieceNameSeen;
    std::size_t pieceNameOf = ~std::size_t(0);
    std::string error;   ///< shown until dismissed
    std::string notice;  ///< status line (saved, autosaved, ...)
    bool help = false;
    bool focusField = false;
};

class SculptApp : private ModeHost, private ToolHost {
public:
    /// Runs in `window`; one that does not draw (HeadlessWindow) runs everything but the drawing.
    SculptApp(Window& window, AppOptions options);
    ~SculptApp();

    /// Runs until the user quits (or the replay ends). @return the exit status.
    int run();
    /// One input, live or replayed.
    void handle(const InputEvent& event);
    /// A command from a key, a menu or a button; if it cannot run now, the status bar says why.
    void execute(Command command);
    /// Why `command` cannot run now ("nothing to undo"), or "" when it can: menus grey it out.
    std::string whyNot(Command command) const;
    /// Every command, added by its owner: the keys, menus, tooltips and Help read it.
    const CommandRegistry& commands() const { return mCommands; }

    Document& document() override { return *mDocument; }
    BrushOptions& brush() override { return mBrush; }
    SurfaceLook& look() { return mView.look(); }
    CameraControl& camera() { return mView.camera(); }
    Dialogs& dialogs() { return mDialogs; }
    const Dialogs& dialogs() const { return mDialogs; }
    RecentFiles& recent() { return mRecent; }
    const StatusFigures& status() const { return mStatus.figures(); }
    bool strokeActive() const { return mTools.get<SculptTool>().holding(); }
    ToolBox& tools() { return mTools; }
    const ToolBox& tools() const { return mTools; }
    bool scalesShown() const { return mView.scales().shown(); }
    bool ghostShown() const { return mView.ghost().shown(); }
    /// The whole-model job running, or nullptr.
    const BackgroundJob* job() const { return mJobs.job(); }
    /// The open mode if it is an M (a MorphMode, an ImportMode...), else nullptr.
    template <typename M>
    M* mode()
    {
        return dynamic_cast<M*>(mMode.get());
    }
    template <typename M>
    const M* mode() const
    {
        return dynamic_cast<const M*>(mMode.get());
    }
    /// The open mode's panel, if one is open.
    void drawModePanel();
    /// Adds a primitive of `type` where the pointer is on the surface (else at the view's centre),
    /// opening the Primitives panel.
    void addPrimitive(SkeletonType type);

    /// A mask operation on the sculpted piece, one undo step (the status bar says when it changed nothing).
    void editMask(MaskOperation operation);
    /// Keeps only (or deletes) the island under the pointer, as a job; says so when none is there.
    void editIslandUnderPointer(bool keep);
    /// Mask Cavities' radius: concave within it is a cavity (0: four voxels).
    double& creaseRadius() { return mCreaseRadius; }
    /// Drills a drain hole at the pointer through the wall to the hollow behind it, one undo step
    /// (radius: the Hollow dialog's); says so when no hollow lies behind.
    void drillDrainHoleUnderPointer();
    /// The print check the clay shows (View > Print Check): wall thickness or overhang, and their
    /// thresholds; its grids are filled in each frame.
    SurfaceTint& printCheck() { return mView.printCheck(); }

    /// Dialog outcomes.
    void confirmPrompt();
    void recover(bool accept);
    void answerUnsaved(bool save, bool discard);
    /// Opens the grid chosen in the grid dialog (nothing: the choice was cancelled).
    void openChosenGrid(std::optional<std::string> grid);
    void openRecent(const std::filesystem::path& path);

private:
    /// The window's own commands (command_table.cpp); the tools add theirs.
    void addCommands();
    void frame();
    /// One pass of the loop: input (live or replayed), autosave, a frame.
    void loopOnce(bool& replayDone);
    /// An exception no handler expected (out of memory, a bug, an OpenVDB error) reached the
    /// loop: the work is saved as a recovery copy, the error shown, and the window goes on.
    void recoverFromInternalError(const std::string& what);
    /// A fault event's internal error (tests of that recovery).
    [[noreturn]] static void raiseFault(const std::string& kind);
    bool idle() const;
    /// Nothing but frames' own state asks for a frame: no drag, no recent input, nothing pending.
    bool quiet() const;
    /// How long the loop may wait for input before its next frame (see inputWait's comment).
    double inputWait() const;
    void autosave();
    /// Writes the recovery copy now, before a file is read: a reader that takes the process down
    /// must not take unsaved work.
    void autosaveNow() override;
    void notify(std::string notice) override { mDialogs.notice = std::move(notice); }
    void startEdit(ModelEdit edit) override;
    // What the tools ask (ToolHost).
    const Viewport& viewport() const override { return mView.viewport(); }
    const CameraControl& camera() const override { return mView.camera(); }
    SurfacePicker& picker() override { return mView.picker(); }
    glm::dvec2 pointer() const override { return {mPointer.x(), mPointer.y()}; }
    int heldMods() const override { return mPointer.held(); }
    JobRunner& jobs() override { return mJobs; }
    void showPlacement(const openvdb::Mat4d& placement) override { mView.display().setPlacement(placement); }
    void awaitFrame(const InputEvent& event, std::size_t stamps) override;
    void startDocument(std::string label, DocumentMaker make, std::function<std::string()> landed) override;
    /// Opens `mode` in place of the one open; the status bar shows its hint.
    void openMode(std::unique_ptr<Mode> mode);
    /// Drops the open mode and what it shows; the document stays as it was.
    void closeMode();
    /// Enter: the open mode hands its result over and closes (an error keeps it open).
    void acceptMode();
    /// Accepts the open mode if it is an M (the menus' Apply Import, Bake Primitives, Keep Frame).
    template <typename M>
    void acceptModeOf()
    {
        if (mode<M>()) acceptMode();
    }
    void drawPanels();
    void routeMouse(const InputEvent& event);
    void routeKey(const InputEvent& event);
    /// While a dialog is open it takes every key: its answers are commands of Scope::Dialog.
    void routeDialogKey(const InputEvent& event);
    void pressButton(const InputEvent& event);
    void releaseButton(const InputEvent& event);
    void dragTo(const InputEvent& event, double dx, double dy);
    /// The hover picked again if it went stale, and the brush cursor placed on it.
    void updateCursor();
    void updateTitle();
    void setDocument(std::unique_ptr<Document> document, bool frameIt);
    bool guardUnsaved(Command again) override;
    void saveTo(const std::filesystem::path& path);
    void showError(const std::string& message) override;
    bool modalOpen() const;
    /// When an event happened on the window's clock (a replayed one: when it was due).
    double arrival(const InputEvent& event) const;
    void writeScreenshot(const std::filesystem::path& path);
    /// Appends the state as a JSON line to `path`, called `name` (if not "").
    void writeReport(const std::filesystem::path& path, const std::string& name);
    void finishReplay();
    std::optional<SurfaceHit> pickAt(double x, double y) override { return mView.pickAt(*mDocument, x, y); }
    SurfaceHit inWorld(const SurfaceHit& hit) const override { return mView.inWorld(*mDocument, hit); }
    /// Brings the drawing of the pieces up to date; another piece sculpted: its measures start again.
    void showPieces();
    void replayStrokes();
    /// Runs `work` (Progress -> Result) as the background job; once it succeeded, `land`
    /// (Result) takes its result on the UI thread: the document's new field, frames, a target.
    template <typename Result, typename WorkFn, typename LandFn>
    void startJob(std::string label, WorkFn work, LandFn land)
    {
        ui::startJob<Result>(*this, std::move(label), std::move(work), std::move(land));
    }
    /// Starts `filter` over a copy of the model as a background job.
    void startFilter(const ModelFilter& filter);
    /// Opens the document at `path` as a job; the old one stays if it fails.
    void startOpen(const std::filesystem::path& path, const std::string& grid = {});
    /// The open job itself: a large model shows its preview first (OpenPreview), then fills in.
    void openInJob(const std::filesystem::path& path, const std::string& grid);
    /// Shows the open job's preview once it is ready, the camera framing it.
    void showOpenPreview();
    /// The command line's document: how its opening ends (a failure ends the program, exit 2),
    /// and when its full detail is on screen.
    void followStartupOpen(JobRunner::Ending ending, const std::string& error);
    /// Writes the surface as a mesh file as a job.
    void startExport(const std::filesystem::path& path);
    /// Reads the file at `path` as the follow brush's target (and the ghost), as a job.
    void startLoadTarget(const std::filesystem::path& path);
    /// Reads the scan or mesh at `path` for the Import panel, as a job.
    void startImportRead(const std::filesystem::path& path);
    /// The Primitives panel, opened if it is not.
    PrimitivesMode& primitivesMode();
    /// Opens the primitives in the scene file at `path` in the Primitives panel.
    void loadScene(const std::filesystem::path& path);
    /// Starts a morph of a copy of the model into the file at `target` as a background job.
    void startMorph(const std::filesystem::path& target, const MorphOptions& options, bool tracked);
    /// Lands a finished job's result (or reports why there is none).
    void pollJob();
    /// Why an edit of the document must wait (a job runs, a mode is open, a gesture), or "".
    std::string waitReason() const override;
    /// True (with waitReason as the notice) if an edit of the document must wait.
    bool busy() override;
    /// Opens `prompt` with `path` in its field, the field focused.
    void openPrompt(Dialogs::Prompt prompt, std::string path = {});
    /// The document's path with `extension` ("doc.ply"), or `fallback` for an unnamed document.
    std::string besideDocument(const char* extension, const char* fallback) const;
    /// What a replay's wait event waits for: a job, or a mode (a morph playing).
    bool holdsReplay() const;

    Window& mWindow;
    AppOptions mOptions;
    GuiContext mGui;  // before the parts whose panels it lays out, gone after them
    DocumentView mView;
    Autosave mAutosave;
    RecentFiles mRecent;
    std::unique_ptr<Document> mDocument;
    BrushOptions mBrush;
    ToolBox mTools;
    CommandRegistry mCommands;
    Dialogs mDialogs;
    StatusTally mStatus;
    std::unique_ptr<EventPlayer> mPlayer;
    JobRunner mJobs;
    std::shared_ptr<OpenPreview> mOpenPreview;  // of the open or import job running, if one is
    std::size_t mPreviewsShown = 0;             // reported: a large document showed one first
    bool mOpeningAtStart = false;               // the command line's document is opening
    std::unique_ptr<Mode> mMode;                // after the viewport and the look: it draws into them
    bool mUnsavedAnswered = false;              // "save changes?" was answered: the command it held runs
    double mLastEventArrival = 0.0;             // when the latest input was due (its replay time, if replayed)
    double mPreviewPendingSince = -1.0;         // a mode's settings changed then, its preview not yet on screen
    std::string mLastJob;                       // how the last job ended: "finished", "cancelled", "failed"
    std::vector<InputEvent> mRecording;

    // Pointer state.
    PointerState mPointer;
    std::string mTitle;
    /// What a drag that is not the tool's does: the camera, a brush setting (F), a mode's handle.
    enum class Drag { None, Orbit, Pan, Zoom, Radius, Strength, Mode };
    Drag mDrag = Drag::None;
    double mDragStartX = 0.0, mDragStartValue = 0.0;
    double mCreaseRadius = 0.0;
    bool mItemActive = false;  // an ImGui item (a text field) was active at the end of the last frame

    // Frame bookkeeping.
    bool mQuit = false;
    int mExitStatus = 0;
    double mLastFrame = 0.0, mLastInput = 0.0;
    std::size_t mRemeshedAtSync = 0, mLastRemeshed = 0;
    std::uint64_t mReportVersion = 0;
    /// Figures for reports, since the previous one: frame times, event-to-screen latencies,
    /// triangles drawn per frame, stamps.
    struct Measures {
        std::vector<double> frameMs, latencyMs, previewLatencyMs, trianglesDrawn;
        std::size_t stamps = 0;
        double pendingSince = -1.0;  // a stamp not yet on screen: when its event arrived
    };
    Measures mMeasures;
    std::vector<std::filesystem::path> mPendingScreenshots;
    std::vector<InputEvent> mPendingReports;
    std::uint64_t mFramesDrawn = 0;
};

}  // namespace sculpt::ui
