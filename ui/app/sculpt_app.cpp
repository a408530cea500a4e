// SPDX-License-Identifier: Apache-2.0
#include "ui/app/sculpt_app.h"

#include "core/base/errors.h"
#include "core/base/text_format.h"
#include "core/field/placed_box.h"
#include "sculpt/session/script_replay.h"
#include "sculpt/session/stroke_script.h"
#include "ui/input/imgui_input.h"
#include "ui/input/input_event.h"
#include "ui/panels/panels.h"
#include "ui/status/process_memory.h"
#include "ui/view/screenshot.h"
#include "ui/window/window.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <nlohmann/json.hpp>
#include <vtkRenderer.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>
#include <new>
#include <thread>

namespace sculpt::ui {

namespace fs = std::filesystem;

namespace {

/// What the window shows until the command line's document is open: an empty level set.
std::unique_ptr<Document> placeholder()
{
    return std::make_unique<Document>(
        FieldImage(makeLevelSetGrid(NewShape{}.voxelSize, FieldImage::kDefaultHalfWidthVoxels)));
}

nlohmann::json vec3Json(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

}  // namespace

SculptApp::SculptApp(Window& window, AppOptions options)
    : mWindow(window), mOptions(std::move(options)), mGui(window.draws()),
      mView(window.width(), window.height(), window.draws(), mOptions.chunkBlocks),
      mWork(placeholder(), Autosave(mOptions.stateDir, mOptions.autosaveSeconds), mOptions.previewTriangles),
      mFiles(mWork, mOptions.stateDir), mTools(static_cast<ToolHost&>(*this)), mModes(static_cast<PanelHost&>(*this)),
      mReplay(mOptions.play, mOptions.record)
{
    mWork.connect({[this] {
                       const std::string gesture = mTools.current().waitReason();
                       return gesture.empty() ? mModes.waitNotice() : gesture;
                   },
                   [this](bool frameIt) { showDocument(frameIt); }});
    showDocument(false);  // the placeholder, while the command line's document opens
    mFiles.openAtStart(mOptions.document, mOptions.grid);
    mBrush.radius = 10.0 * mWork.document().session().field().voxelSize();
    mTools.addCommands(mCommands);
    addCommands();
    mWork.addCommands(mCommands);
    addPanelCommands(mCommands, *this);
    mModes.addCommands(mCommands);

    mWindow.setListener([this](const InputEvent& e) {
        if (!mReplay.player()) handle(e);
        else if (e.type == EventType::Resize) mView.viewport().resize(e.width, e.height);  // the replay's own resize
    });
}

SculptApp::~SculptApp() { mWindow.setListener({}); }

double SculptApp::time() const { return mWindow.time(); }

void SculptApp::addCommands()
{
    const auto adjust = [this](ViewDrag::Kind setting) {
        return [this, setting] { mDrag.adjust(setting, mPointer.x(), mBrush); };
    };
    mCommands.add({Command::RadiusDrag,
                   "Radius",
                   "Then move the mouse to size the brush; click or Enter to keep, Esc to undo",
                   {{GLFW_KEY_F}},
                   nullptr,
                   adjust(ViewDrag::Kind::Radius)});
    mCommands.add({Command::StrengthDrag,
                   "Strength",
                   "Then move the mouse to set the strength",
                   {{GLFW_KEY_F, kShift}},
                   nullptr,
                   adjust(ViewDrag::Kind::Strength)});
    mCommands.add({Command::Quit,
                   "Quit",
                   "Close Sculpt (asks first if there are unsaved changes)",
                   {{GLFW_KEY_Q, kControl}},
                   nullptr,
                   [this] {
                       if (mFiles.guardUnsaved(Command::Quit))
                           mQuit = true;  // a running job is cancelled on the way out
                   }});
}

void SculptApp::execute(Command command)
{
    if (mTools.get<SculptTool>().holding()) return;  // nothing interrupts a stroke
    const std::string blocked = mCommands.whyNot(command);
    if (blocked.empty()) mCommands.row(command).run();
    else mWork.notices().say(blocked);
}

void SculptApp::showDocument(bool frameIt)
{
    mStatus.reset();
    mFrames.restart(mWork.document().session());
    mView.show(mWork.document(), frameIt);
}

// ---------------------------------------------------------------------------------------------
// Frames

void SculptApp::updateCursor()
{
    const bool picking = !mDrag.active() && (!mTools.current().holding() || mTools.current().showsBrush());
    mView.hover(mWork.document(), mPointer.x(), mPointer.y(), picking);
    const Mode* mode = mModes.get();
    const bool shown =
        mTools.current().showsBrush() && !ImGui::GetIO().WantCaptureMouse && (!mode || mode->showsBrush());
    mView.placeCursor(mWork.document(), shown, mTools.get<SculptTool>().toolUnder(mPointer.current()), mBrush);
}

void SculptApp::frame()
{
    const double now = mWindow.time();
    if (std::optional<OpenPreview::Surface> preview = mWork.takePreview()) {  // before its job lands
        mView.showPreview(*preview);
        if (mFiles.openingAtStart()) std::cout << "sculpt-ui: preview in " << formatSeconds(now) << " s" << std::endl;
    }
    const JobRunner::Outcome landed = mWork.poll();
    if (landed.ending != JobRunner::Ending::Running) {
        mFrames.wake(now);     // show the notice
        mView.redrawPieces();  // a push that did not land leaves its piece where it was
        if (landed.ending != JobRunner::Ending::Finished) mView.display().dropPreview();
    }
    Document& document = mWork.document();
    document.session().updateMesh();   // once per frame: a stroke's events only stamp
    if (mView.syncPieces(document)) {  // another piece sculpted: its measures start again
        mStatus.reset();
        mFrames.restart(document.session());
    }
    const double sinceLast = mFrames.begin(now, document.session());
    Mode* mode = mModes.get();
    if (mode && mode->sync(now)) mFrames.awaitPreview();
    const bool stroking = mTools.get<SculptTool>().holding();
    mView.sync(document, mode ? mode->shownMesher() : nullptr, mode && mode->hidesDocument(), now, stroking,
               mStatus.triangles() <= mOptions.lodTriangles, mBrush, mStatus.modelSize());
    switch (mFiles.followStart(landed.ending, landed.error, mView.display().pendingChunks() == 0)) {
    case DocumentFiles::Start::Landed: mBrush.radius = 10.0 * document.session().field().voxelSize(); break;
    case DocumentFiles::Start::Shown:
        std::cout << "sculpt-ui: full detail in " << formatSeconds(mWindow.time()) << " s" << std::endl;
        break;
    case DocumentFiles::Start::None: break;
    }
    mStatus.countUploads(mView.display());
    mStatus.refresh(mWork.document(), mView.display(), mView.pieces().trianglesShown(), stroking, !stroking,
                    mFrames.framesDrawn() % 30 == 0);
    updateCursor();
    mWindow.setTitle("Sculpt - " + mWork.document().title());

    Viewport& viewport = mView.viewport();
    viewport.renderer()->ResetCameraClippingRange();
    viewport.render();
    mGui.beginFrame(viewport.width(), viewport.height(), sinceLast);
    drawPanels();
    mGui.endFrame(viewport.width(), viewport.height());
    // A report's own checksum and whole-model figures would weigh on the frames it reports next.
    const bool reporting = mReplay.asked();
    writeAsked();
    mWindow.swapBuffers();
    if (mOptions.slowFramesMs > 0) std::this_thread::sleep_for(std::chrono::milliseconds(mOptions.slowFramesMs));
    mStatus.setFrameMs(mFrames.end(now, mWindow.time(), double(mView.display().trianglesDrawn()), !reporting));
}

void SculptApp::drawPanels()
{
    drawMainMenu(*this);
    drawToolPanel(*this);
    drawHistoryPanel(*this);
    drawPiecesPanel(*this);
    drawStatusBar(*this);
    drawSliceLabels(*this);
    drawDialogs(*this);
    drawJobPanel(*this);
    mModes.drawPanel();
    if (mDialogs.help) drawHelpPanel(*this);
    Tool& tool = mTools.current();
    tool.drawOverlay();
    if (!mView.hovered() && tool.showsBrush() && !tool.holding() && !ImGui::GetIO().WantCaptureMouse &&
        !mDrag.active() && mPointer.x() >= 0) {
        // Off the model: the brush as a screen circle of its size at the model's depth.
        const double pixels =
            mBrush.radius / std::max(1e-12, mView.viewport().pixelSizeAt(mView.camera().focalPoint()));
        ImGui::GetForegroundDrawList()->AddCircle(ImVec2(float(mPointer.x()), float(mPointer.y())), float(pixels),
                                                  IM_COL32(255, 255, 255, 140), 48, 1.5f);
    }
    if (mDrag.adjusting()) ImGui::SetTooltip("%s", mDrag.hint(mBrush).c_str());
}

// ---------------------------------------------------------------------------------------------
// The loop

bool SculptApp::quiet() const
{
    constexpr double kSettleSeconds = 0.5;  // frames go on a little after the last input (hover, LOD)
    const Mode* mode = mModes.get();
    return !mDrag.active() && !mTools.current().holding() && mWindow.time() - mFrames.lastInput() > kSettleSeconds &&
           !mReplay.asked() && mView.display().pendingChunks() == 0 && !(mode && mode->holdsReplay());
}

double SculptApp::inputWait() const
{
    // While only a job's progress bar changes, ten frames a second show it: llvmpipe drawing at
    // full rate would take a core from the job. Input still wakes the loop at once.
    constexpr double kJobFrameSeconds = 0.1;
    constexpr double kIdleWakeSeconds = 0.25;  // asleep until input, waking to autosave
    if (!quiet()) return 0.0;
    return mWork.jobs().running() ? kJobFrameSeconds : kIdleWakeSeconds;
}

bool SculptApp::holdsReplay() const
{
    const Mode* mode = mModes.get();
    return mWork.jobs().running() || (mode && mode->holdsReplay());
}

void SculptApp::loopOnce(bool& replayDone)
{
    EventPlayer* player = mReplay.player();
    if (player && !holdsReplay()) player->resume(mWindow.time());  // a wait event's job ended
    const bool replaying = player && !player->finished();
    if (replaying) {
        for (const InputEvent& event : player->take(mWindow.time())) {
            if (event.type == EventType::Resize) mWindow.resize(event.width, event.height);  // as a user would
            handle(event);
        }
        // Held for a job or playback (wait event): frames go on, at the job's pace.
        mWindow.pollEvents(player->held() ? inputWait() : 0.0);
    } else {
        if (player && !replayDone) {
            replayDone = true;
            finishReplay();
            if (mQuit) return;
        }
        mWindow.pollEvents(inputWait());
    }
    if (mWork.autosaveIfDue(mWindow.time(), mTools.get<SculptTool>().holding()))
        mFrames.wake(mWindow.time());  // show the notice
    if (replaying || !quiet() || mWork.jobs().running()) frame();
}

void SculptApp::recoverFromInternalError(const std::string& what)
{
    abandonImGuiFrame();
    std::string saved;
    try {  // what failed may have been a stroke: end it, so that it is kept and saved
        mTools.current().finish();
        mDrag.end(false, mBrush);
        std::string error;
        const Document& document = mWork.document();
        if (mWork.autosave().save(document, error)) saved = mWork.autosave().recoveryFile(document.path()).string();
    } catch (const std::exception&) {  // out of memory, say: the message below still goes out
    }
    mWork.notices().fail("internal error: " + what +
                         (saved.empty() ? std::string() : "; your work is saved in " + saved + ",") +
                         " save it under a new name before going on; if the view misbehaves, restart Sculpt and "
                         "recover it");
}

int SculptApp::run()
{
    frame();  // the first frame compiles shaders and uploads everything: 150-400 ms here
    std::cout << "sculpt-ui: first frame in " << formatSeconds(mWindow.time()) << " s" << std::endl;
    EventPlayer* player = mReplay.player();
    const bool scripted = player || !mOptions.strokes.empty() || !mOptions.screenshot.empty();
    while (scripted && mFiles.openingAtStart()) {  // a script starts on the document, in full detail
        mWindow.pollEvents(inputWait());
        frame();
    }
    if (!mOptions.strokes.empty()) replayStrokes();
    if (!player && scripted) finishReplay();
    if (player) player->start(mWindow.time());
    bool replayDone = false;
    while (!mQuit) {
        try {
            loopOnce(replayDone);
        } catch (const InputError& e) {
            if (mFiles.openingAtStart()) throw;  // the command line's document failed: exit 2, as before the window
            // What the user gave was refused where no handler expected it: said as it is.
            abandonImGuiFrame();
            mTools.current().finish();
            mDrag.end(false, mBrush);
            mWork.notices().fail(e.what());
        } catch (const std::bad_alloc&) {
            recoverFromInternalError("out of memory");
        } catch (const std::exception& e) {
            recoverFromInternalError(e.what());
        }
    }
    mReplay.save();
    mWork.autosave().discard(mWork.document().path());  // a clean quit: nothing to recover
    return mExitStatus;
}

// ---------------------------------------------------------------------------------------------
// What scripts and tests ask for

void SculptApp::replayStrokes()
{
    const StrokeScript script = readStrokeScript(mOptions.strokes);
    ReplayReport done;
    for (std::size_t i = 0; i < script.events.size(); ++i) {
        const std::string where = mOptions.strokes.string() + ": events[" + std::to_string(i) + "]";
        applyScriptEvent(mWork.document(), script.events[i], where, done);
        frame();  // the sculpt grows on screen, one event per frame
    }
}

void SculptApp::finishReplay()
{
    try {
        if (!mOptions.saveAs.empty()) mFiles.saveTo(mOptions.saveAs);
        if (!mOptions.exportMesh.empty())
            for (const std::string& line : mWork.document().exportMesh(mOptions.exportMesh))
                std::cout << "sculpt-ui: " << line << "\n";
        if (!mOptions.strokeLog.empty()) mWork.document().saveStrokes(mOptions.strokeLog);
    } catch (const InputError& e) {
        mWork.notices().fail(e.what());
        mExitStatus = 2;
    }
    if (!mOptions.screenshot.empty()) {
        mReplay.askScreenshot(mOptions.screenshot);
        frame();
    }
    if (!mOptions.stay) mQuit = true;
}

void SculptApp::writeAsked()
{
    for (const InputEvent& asked : mReplay.takeAsked()) {
        if (asked.type == EventType::Report) writeReport(asked.text, asked.name);
        else if (!mWindow.draws())
            mWork.notices().fail(asked.text + ": no screenshot without a window (headless: nothing is drawn)");
        else if (!writeScreenshot(asked.text, mView.viewport().width(), mView.viewport().height()))
            mWork.notices().fail(asked.text + ": cannot write the screenshot");
        else std::cout << "sculpt-ui: screenshot " << asked.text << std::endl;
    }
}

void SculptApp::writeReport(const fs::path& path, const std::string& name)
{
    nlohmann::json r;
    if (!name.empty()) r["name"] = name;
    mFrames.report(r, mWork.document().session());
    mWork.report(r);
    mFiles.report(r);
    mDialogs.report(r);
    mStatus.report(r);
    mView.report(r);
    mModes.report(r);
    mBrush.report(r);
    r["tool_chosen"] = mTools.current().name();
    mTools.current().report(r);
    const std::optional<SurfaceHit> hit = mView.pickAt(mWork.document(), mPointer.x(), mPointer.y());
    r["pick"] =
        hit ? nlohmann::json{{"hit", true}, {"position", vec3Json(hit->position)}, {"normal", vec3Json(hit->normal)}}
            : nlohmann::json{{"hit", false}};
    r["peak_rss"] = peakResidentBytes();
    std::ofstream out(path, std::ios::app);
    out << r.dump() << "\n";
    if (!out) mWork.notices().fail(path.string() + ": cannot write the report");
}

}  // namespace sculpt::ui
