#include "ui/app/sculpt_app.h"

#include "core/base/errors.h"
#include "core/base/text_format.h"
#include "core/field/placed_box.h"
#include "sculpt/session/script_replay.h"
#include "ui/input/imgui_input.h"
#include "ui/panels/panels.h"
#include "ui/window/window.h"

#include <imgui.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <new>
#include <thread>

namespace sculpt::ui {

namespace fs = std::filesystem;

namespace {

std::unique_ptr<Document> openOrCreate(const fs::path& path, const std::string& grid)
{
    if (path.empty()) return std::make_unique<Document>(Document::create(NewShape{}));
    return std::make_unique<Document>(Document::open(path, {}, nullptr, grid));
}

}  // namespace

SculptApp::SculptApp(Window& window, AppOptions options)
    : mWindow(window), mOptions(std::move(options)), mGui(window.draws()),
      mView(window.width(), window.height(), window.draws(), mOptions.chunkBlocks),
      mAutosave(mOptions.stateDir, mOptions.autosaveSeconds), mRecent(mOptions.stateDir), mTools(*this)
{
    if (!mOptions.play.empty()) mPlayer = std::make_unique<EventPlayer>(readInputEvents(mOptions.play.string()));
    mDialogs.recovery = mAutosave.pending(mOptions.document);
    if (!mOptions.document.empty() && !mDialogs.recovery) {
        // Opened as a job: the window is up at once, a large model's preview shortly after.
        setDocument(std::make_unique<Document>(
                        FieldImage(makeLevelSetGrid(NewShape{}.voxelSize, FieldImage::kDefaultHalfWidthVoxels))),
                    false);
        mOpeningAtStart = true;
        openInJob(mOptions.document, mOptions.grid);
    } else {  // offering its recovery asks for the document as it is
        setDocument(openOrCreate(mOptions.document, mOptions.grid), true);
    }
    mBrush.radius = 10.0 * mDocument->session().field().voxelSize();
    if (!mOptions.document.empty()) mRecent.add(mOptions.document);
    mTools.addCommands(mCommands);
    addCommands();

    mWindow.setListener([this](const InputEvent& e) {
        if (!mPlayer) handle(e);
        else if (e.type == EventType::Resize) mView.viewport().resize(e.width, e.height);  // the replay's own resize
    });
}

SculptApp::~SculptApp() { mWindow.setListener({}); }

void SculptApp::setDocument(std::unique_ptr<Document> document, bool frameIt)
{
    mDocument = std::move(document);
    mStatus.reset();
    mRemeshedAtSync = mDocument->session().remeshedBlocks();
    mReportVersion = mDocument->session().mesher()->version();
    mView.show(*mDocument, frameIt);
}

void SculptApp::showPieces()
{
    if (!mView.syncPieces(*mDocument)) return;
    mStatus.reset();
    mRemeshedAtSync = mDocument->session().remeshedBlocks();
}

double SculptApp::arrival(const InputEvent& event) const { return mPlayer ? mPlayer->arrival(event) : event.time; }

bool SculptApp::modalOpen() const
{
    return mDialogs.prompt != Dialogs::Prompt::None || mDialogs.afterUnsaved || mDialogs.recovery ||
           mDialogs.gridChoice || !mDialogs.error.empty();
}

void SculptApp::showError(const std::string& message)
{
    mDialogs.error = message;
    std::cerr << "sculpt-ui: " << message << "\n";
}

// ---------------------------------------------------------------------------------------------
// Frames

void SculptApp::updateCursor()
{
    const bool picking = mDrag == Drag::None && (!mTools.current().holding() || mTools.current().showsBrush());
    mView.hover(*mDocument, mPointer.x(), mPointer.y(), picking);
    const bool shown =
        mTools.current().showsBrush() && !ImGui::GetIO().WantCaptureMouse && (!mMode || mMode->showsBrush());
    mView.placeCursor(*mDocument, shown, mTools.get<SculptTool>().toolUnder(mPointer.current()), mBrush);
}

void SculptApp::updateTitle()
{
    const std::string title = "Sculpt - " + mDocument->title();
    if (title != mTitle) mWindow.setTitle(title);
    mTitle = title;
}

void SculptApp::frame()
{
    const double now = mWindow.time();
    showOpenPreview();  // before the job lands: a preview taken after would hide its document
    pollJob();
    mDocument->session().updateMesh();  // once per frame: a stroke's events only stamp
    showPieces();

    const SculptSession& session = mDocument->session();
    const std::size_t remeshed = session.remeshedBlocks();
    mLastRemeshed += remeshed - mRemeshedAtSync;
    mRemeshedAtSync = remeshed;
    if (mMode && mMode->sync(now) && mPreviewPendingSince < 0.0) mPreviewPendingSince = mLastEventArrival;
    mView.sync(*mDocument, mMode ? mMode->shownMesher() : nullptr, mMode && mMode->hidesDocument(), now, strokeActive(),
               mStatus.triangles() <= mOptions.lodTriangles, mBrush, mStatus.modelSize());
    if (mOpeningAtStart) followStartupOpen(JobRunner::Ending::Running, {});
    mStatus.countUploads(mView.display());
    mStatus.refresh(*mDocument, mView.display(), mView.pieces().trianglesShown(), strokeActive(), !strokeActive(),
                    mFramesDrawn % 30 == 0);
    updateCursor();
    updateTitle();

    Viewport& viewport = mView.viewport();
    viewport.renderer()->ResetCameraClippingRange();
    viewport.render();
    mGui.beginFrame(viewport.width(), viewport.height(), now - mLastFrame);
    drawPanels();
    mItemActive = ImGui::IsAnyItemActive();
    mGui.endFrame(viewport.width(), viewport.height());
    for (const fs::path& path : mPendingScreenshots) writeScreenshot(path);
    // A report's own checksum and whole-model figures would weigh on the frames it reports next.
    const bool reporting = !mPendingReports.empty();
    for (const InputEvent& report : mPendingReports) writeReport(report.text, report.name);
    mPendingScreenshots.clear();
    mPendingReports.clear();
    mWindow.swapBuffers();
    if (mOptions.slowFramesMs > 0) std::this_thread::sleep_for(std::chrono::milliseconds(mOptions.slowFramesMs));

    const double end = mWindow.time();
    const double frameMs = 1000.0 * (end - now);
    mStatus.setFrameMs(frameMs);
    if (!reporting) {
        mMeasures.frameMs.push_back(frameMs);
        mMeasures.trianglesDrawn.push_back(double(mView.display().trianglesDrawn()));
    }
    if (mPreviewPendingSince >= 0.0) {
        mMeasures.previewLatencyMs.push_back(1000.0 * (end - mPreviewPendingSince));
        mPreviewPendingSince = -1.0;
    }
    if (mMeasures.pendingSince >= 0.0) {
        mMeasures.latencyMs.push_back(1000.0 * (end - mMeasures.pendingSince));
        mMeasures.pendingSince = -1.0;
    }
    mLastFrame = now;
    ++mFramesDrawn;
}

void SculptApp::drawPanels()
{
    drawMainMenu(*this);
    drawToolPanel(*this);
    drawHistoryPanel(*this);
    drawPiecesPanel(*this);
    drawStatusBar(*this);
    drawDialogs(*this);
    drawJobPanel(*this);
    drawModePanel();
    if (mDialogs.help) drawHelpPanel(*this);
    mTools.current().drawOverlay();
    if (!mView.hovered() && mTools.current().showsBrush() && !mTools.current().holding() &&
        !ImGui::GetIO().WantCaptureMouse && mDrag == Drag::None && mPointer.x() >= 0) {
        // Off the model: the brush as a screen circle of its size at the model's depth.
        const double pixels =
            mBrush.radius / std::max(1e-12, mView.viewport().pixelSizeAt(mView.camera().focalPoint()));
        ImGui::GetForegroundDrawList()->AddCircle(ImVec2(float(mPointer.x()), float(mPointer.y())), float(pixels),
                                                  IM_COL32(255, 255, 255, 140), 48, 1.5f);
    }
    if (mDrag == Drag::Radius || mDrag == Drag::Strength) {
        ImGui::SetTooltip(mDrag == Drag::Radius ? "radius %.3g (move, click to keep, Esc to cancel)"
                                                : "strength %.2f (move, click to keep, Esc to cancel)",
                          mDrag == Drag::Radius ? mBrush.radius : mBrush.strength);
    }
}

// ---------------------------------------------------------------------------------------------
// The loop

void SculptApp::replayStrokes()
{
    const StrokeScript script = readStrokeScript(mOptions.strokes);
    ReplayReport done;
    for (std::size_t i = 0; i < script.events.size(); ++i) {
        const std::string where = mOptions.strokes.string() + ": events[" + std::to_string(i) + "]";
        applyScriptEvent(*mDocument, script.events[i], where, done);
        frame();  // the sculpt grows on screen, one event per frame
    }
}

void SculptApp::finishReplay()
{
    try {
        if (!mOptions.saveAs.empty()) saveTo(mOptions.saveAs);
        if (!mOptions.exportMesh.empty())
            for (const std::string& line : mDocument->exportMesh(mOptions.exportMesh))
                std::cout << "sculpt-ui: " << line << "\n";
        if (!mOptions.strokeLog.empty()) mDocument->saveStrokes(mOptions.strokeLog);
    } catch (const InputError& e) {
        showError(e.what());
        mExitStatus = 2;
    }
    if (!mOptions.screenshot.empty()) {
        mPendingScreenshots.push_back(mOptions.screenshot);
        frame();
    }
    if (!mOptions.stay) mQuit = true;
}

bool SculptApp::quiet() const
{
    constexpr double kSettleSeconds = 0.5;  // frames go on a little after the last input (hover, LOD)
    return mDrag == Drag::None && !mTools.current().holding() && mWindow.time() - mLastInput > kSettleSeconds &&
           mPendingScreenshots.empty() && mPendingReports.empty() && mView.display().pendingChunks() == 0 &&
           !(mMode && mMode->holdsReplay());
}

bool SculptApp::idle() const { return quiet() && !mJobs.running(); }

double SculptApp::inputWait() const
{
    // While only a job's progress bar changes, ten frames a second show it: llvmpipe drawing at
    // full rate would take a core from the job. Input still wakes the loop at once.
    constexpr double kJobFrameSeconds = 0.1;
    constexpr double kIdleWakeSeconds = 0.25;  // asleep until input, waking to autosave
    if (!quiet()) return 0.0;
    return mJobs.running() ? kJobFrameSeconds : kIdleWakeSeconds;
}

void SculptApp::autosave()
{
    std::string error;
    if (mAutosave.tick(*mDocument, mWindow.time(), strokeActive(), error)) {
        mDialogs.notice = "autosaved to " + mAutosave.recoveryFile(mDocument->path()).string();
        std::cout << "sculpt-ui: " << mDialogs.notice << std::endl;
        mLastInput = mWindow.time();  // show the notice
    }
    if (!error.empty()) mDialogs.notice = error;
}

void SculptApp::autosaveNow()
{
    std::string error;
    if (mAutosave.save(*mDocument, error))
        std::cout << "sculpt-ui: autosaved to " << mAutosave.recoveryFile(mDocument->path()).string() << std::endl;
    if (!error.empty()) mDialogs.notice = error;
}

void SculptApp::loopOnce(bool& replayDone)
{
    if (mPlayer && !holdsReplay()) mPlayer->resume(mWindow.time());  // a wait event's job ended
    const bool replaying = mPlayer && !mPlayer->finished();
    if (replaying) {
        for (const InputEvent& event : mPlayer->take(mWindow.time())) {
            if (event.type == EventType::Resize) mWindow.resize(event.width, event.height);  // as a user would
            handle(event);
        }
        // Held for a job or playback (wait event): frames go on, at the job's pace.
        mWindow.pollEvents(mPlayer->held() ? inputWait() : 0.0);
    } else {
        if (mPlayer && !replayDone) {
            replayDone = true;
            finishReplay();
            if (mQuit) return;
        }
        mWindow.pollEvents(inputWait());
    }
    autosave();
    if (replaying || !idle()) frame();
}

void SculptApp::recoverFromInternalError(const std::string& what)
{
    abandonImGuiFrame();
    std::string saved;
    try {  // what failed may have been a stroke: end it, so that it is kept and saved
        mTools.current().finish();
        mDrag = Drag::None;
        std::string error;
        if (mAutosave.save(*mDocument, error)) saved = mAutosave.recoveryFile(mDocument->path()).string();
    } catch (const std::exception&) {  // out of memory, say: the message below still goes out
    }
    showError("internal error: " + what + (saved.empty() ? std::string() : "; your work is saved in " + saved + ",") +
              " save it under a new name before going on; if the view misbehaves, restart Sculpt and recover it");
}

int SculptApp::run()
{
    frame();  // the first frame compiles shaders and uploads everything: 150-400 ms here
    std::cout << "sculpt-ui: first frame in " << formatSeconds(mWindow.time()) << " s" << std::endl;
    const bool scripted = mPlayer || !mOptions.strokes.empty() || !mOptions.screenshot.empty();
    while (scripted && mOpeningAtStart) {  // a script starts on the document, in full detail
        mWindow.pollEvents(inputWait());
        frame();
    }
    if (!mOptions.strokes.empty()) replayStrokes();
    if (!mPlayer && scripted) finishReplay();
    if (mPlayer) mPlayer->start(mWindow.time());
    bool replayDone = false;
    while (!mQuit) {
        try {
            loopOnce(replayDone);
        } catch (const InputError& e) {
            if (mOpeningAtStart) throw;  // the command line's document failed: exit 2, as before the window
            // What the user gave was refused where no handler expected it: said as it is.
            abandonImGuiFrame();
            mTools.current().finish();
            mDrag = Drag::None;
            showError(e.what());
        } catch (const std::bad_alloc&) {
            recoverFromInternalError("out of memory");
        } catch (const std::exception& e) {
            recoverFromInternalError(e.what());
        }
    }
    if (!mOptions.record.empty()) writeInputEvents(mRecording, mOptions.record.string());
    mAutosave.discard(mDocument->path());  // a clean quit: nothing to recover
    return mExitStatus;
}

}  // namespace sculpt::ui
