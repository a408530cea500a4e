// SculptApp: what each command does, and the dialogs' outcomes.

#include "core/base/atomic_file.h"
#include "core/base/errors.h"
#include "core/primitives/scene_file.h"
#include "sculpt/session/morph_run.h"
#include "ui/app/sculpt_app.h"
#include "ui/modes/import_mode.h"
#include "ui/modes/morph_mode.h"
#include "ui/modes/primitives_mode.h"
#include "ui/window/app_window.h"

#include <algorithm>
#include <iostream>
#include <utility>

namespace sculpt::ui {

namespace fs = std::filesystem;

namespace {

void toggle(bool& flag) { flag = !flag; }

}  // namespace

void SculptApp::execute(Command command)
{
    if (mStroke.active()) return;  // nothing interrupts a stroke
    const auto tool = [this](BrushTool t) { mBrush.tool = t; };
    switch (command) {
    case Command::ToolAdd: tool(BrushTool::Add); break;
    case Command::ToolCarve: tool(BrushTool::Carve); break;
    case Command::ToolInflate: tool(BrushTool::Inflate); break;
    case Command::ToolDeflate: tool(BrushTool::Deflate); break;
    case Command::ToolSmooth: tool(BrushTool::Smooth); break;
    case Command::ToolFlatten: tool(BrushTool::Flatten); break;
    case Command::ToolGrab: tool(BrushTool::Grab); break;
    case Command::ToolPinch: tool(BrushTool::Pinch); break;
    case Command::ToolFollow:
        tool(BrushTool::Follow);
        if (!mBrush.target.shape) mDialogs.notice = "the follow brush needs a target: File > Load Target (Ctrl+T)";
        break;
    case Command::ToolPrimitive: tool(BrushTool::Primitive); break;
    case Command::RadiusDrag: mDrag = Drag::Radius, mDragStartX = mMouseX, mDragStartValue = mBrush.radius; break;
    case Command::StrengthDrag: mDrag = Drag::Strength, mDragStartX = mMouseX, mDragStartValue = mBrush.strength; break;
    case Command::RadiusSmaller:
        mBrush.radius = std::max(0.5 * mDocument->session().field().voxelSize(), mBrush.radius * 0.8);
        break;
    case Command::RadiusLarger: mBrush.radius *= 1.25; break;
    case Command::SymmetryX: toggle(mBrush.symmetry.x); break;
    case Command::SymmetryY: toggle(mBrush.symmetry.y); break;
    case Command::SymmetryZ: toggle(mBrush.symmetry.z); break;
    case Command::Undo:
        if (!busy() && !mDocument->undo()) mDialogs.notice = "nothing to undo";
        break;
    case Command::Redo:
        if (!busy() && !mDocument->redo()) mDialogs.notice = "nothing to redo";
        break;
    case Command::New:
        if (!busy() && guardUnsaved(command)) mDialogs.prompt = Dialogs::Prompt::New;
        break;
    case Command::Open:
        if (!busy() && guardUnsaved(command))
            mDialogs.prompt = Dialogs::Prompt::Open, mDialogs.path.clear(), mDialogs.focusField = true;
        break;
    case Command::Save:
        if (mDocument->path().empty()) execute(Command::SaveAs);
        else saveTo(mDocument->path());
        break;
    case Command::SaveAs:
        mDialogs.prompt = Dialogs::Prompt::SaveAs, mDialogs.path = mDocument->path().string(),
        mDialogs.focusField = true;
        break;
    case Command::MorphTo:
        if (busy()) break;
        mDialogs.prompt = Dialogs::Prompt::Morph, mDialogs.path = mBrush.target.path.string(),
        mDialogs.focusField = true;
        break;
    case Command::LoadTarget:
        if (busy()) break;
        mDialogs.prompt = Dialogs::Prompt::Target, mDialogs.path = mBrush.target.path.string(),
        mDialogs.focusField = true;
        break;
    case Command::MorphPlay:
        if (MorphMode* morph = mode<MorphMode>()) morph->frames().togglePlay(mWindow.time());
        break;
    case Command::StepUp:
    case Command::StepDown:
        if (mMode) mMode->step(command == Command::StepUp ? 1 : -1);
        break;
    case Command::Import:
        if (busy()) break;
        mDialogs.prompt = Dialogs::Prompt::Import, mDialogs.path.clear(), mDialogs.focusField = true;
        break;
    case Command::ApplyImport: acceptModeOf<ImportMode>(); break;
    case Command::AddPrimitive: addPrimitive(SkeletonType::Point); break;
    case Command::RemovePrimitive:
        if (PrimitivesMode* primitives = mode<PrimitivesMode>()) primitives->draft().removeSelected();
        break;
    case Command::BakePrimitives: acceptModeOf<PrimitivesMode>(); break;
    case Command::LoadScene:
        if (mode<PrimitivesMode>() || !busy())
            mDialogs.prompt = Dialogs::Prompt::LoadScene, mDialogs.path.clear(), mDialogs.focusField = true;
        break;
    case Command::SaveScene:
        if (mode<PrimitivesMode>())
            mDialogs.prompt = Dialogs::Prompt::SaveScene, mDialogs.path = "scene.json", mDialogs.focusField = true;
        else mDialogs.notice = "no primitives to save: Shift+A adds one";
        break;
    case Command::ToggleXRay: mLook.setXRay(!mLook.xray()); break;
    case Command::MorphKeep: acceptModeOf<MorphMode>(); break;
    case Command::MorphExport:
        if (mode<MorphMode>())
            mDialogs.prompt = Dialogs::Prompt::MorphExport, mDialogs.path = "morph", mDialogs.focusField = true;
        break;
    case Command::ExportMesh:
        mDialogs.prompt = Dialogs::Prompt::ExportMesh, mDialogs.focusField = true;
        mDialogs.path =
            mDocument->path().empty() ? "sculpt.ply" : fs::path(mDocument->path()).replace_extension(".ply").string();
        break;
    case Command::SaveStrokes:
        mDialogs.prompt = Dialogs::Prompt::SaveStrokes, mDialogs.focusField = true;
        mDialogs.path = mDocument->path().empty()
                            ? "strokes.json"
                            : fs::path(mDocument->path()).replace_extension(".strokes.json").string();
        break;
    case Command::Quit:
        if (guardUnsaved(command)) mQuit = true;  // a running job is cancelled on the way out
        break;
    case Command::SmoothModel:
    case Command::OffsetModel:
        if (busy()) break;
        mDialogs.filter.kind = command == Command::SmoothModel ? ModelFilter::Kind::Smooth : ModelFilter::Kind::Offset;
        mDialogs.prompt = command == Command::SmoothModel ? Dialogs::Prompt::SmoothModel : Dialogs::Prompt::OffsetModel;
        mDialogs.focusField = true;
        break;
    case Command::FrameModel: frameModel(); break;
    case Command::ViewFront: mCamera.axisView(AxisView::Front); break;
    case Command::ViewBack: mCamera.axisView(AxisView::Back); break;
    case Command::ViewRight: mCamera.axisView(AxisView::Right); break;
    case Command::ViewLeft: mCamera.axisView(AxisView::Left); break;
    case Command::ViewTop: mCamera.axisView(AxisView::Top); break;
    case Command::ViewBottom: mCamera.axisView(AxisView::Bottom); break;
    case Command::OrbitLeft: mCamera.orbitDegrees(-15.0, 0.0); break;
    case Command::OrbitRight: mCamera.orbitDegrees(15.0, 0.0); break;
    case Command::OrbitUp: mCamera.orbitDegrees(0.0, -15.0); break;
    case Command::OrbitDown: mCamera.orbitDegrees(0.0, 15.0); break;
    case Command::ZoomIn: mCamera.zoom(1.25); break;
    case Command::ZoomOut: mCamera.zoom(0.8); break;
    case Command::NextShading: mLook.setShading(Shading((int(mLook.shading()) + 1) % 4)); break;
    case Command::ToggleFlat: mLook.setFlat(!mLook.flat()); break;
    case Command::ToggleWireframe: mLook.setWireframe(!mLook.wireframe()); break;
    case Command::ToggleScales: mScales.setShown(!mScales.shown()); break;
    case Command::ToggleGhost: mGhost.setShown(!mGhost.shown()); break;
    case Command::ToggleTrackball: toggle(mCamera.trackball); break;
    case Command::ToggleHelp: toggle(mDialogs.help); break;
    case Command::Confirm: acceptMode(); break;
    case Command::Cancel:
        if (mJobs.running()) mJobs.cancel();
        else closeMode();
        break;
    }
    mHoverValid = false;
}

bool SculptApp::guardUnsaved(Command again)
{
    if (!mDocument->modified() || mUnsavedAnswered) return true;
    mDialogs.afterUnsaved = again;
    return false;
}

void SculptApp::answerUnsaved(bool save, bool discard)
{
    const std::optional<Command> then = mDialogs.afterUnsaved;
    mDialogs.afterUnsaved.reset();
    if (!then || (!save && !discard)) return;  // cancelled
    if (save) {
        if (mDocument->path().empty()) {
            execute(Command::SaveAs);  // the user names it, then repeats the command
            return;
        }
        saveTo(mDocument->path());
        if (mDocument->modified()) return;  // the save failed: the error is shown
    }
    if (discard) mAutosave.discard(mDocument->path());
    mUnsavedAnswered = true;  // the command runs as if there were nothing to save, once
    execute(*then);
    mUnsavedAnswered = false;
}

void SculptApp::saveTo(const fs::path& path)
{
    try {
        const fs::path previous = mDocument->path();
        mDocument->saveAs(path);
        mAutosave.discard(previous);
        mAutosave.discard(path);
        mRecent.add(path);
        mDialogs.notice = "saved " + path.string();
        std::cout << "sculpt-ui: " << mDialogs.notice << std::endl;
    } catch (const InputError& e) {
        showError(e.what());
    }
}

void SculptApp::openRecent(const fs::path& path)
{
    if (!guardUnsaved(Command::Open)) return;
    mDialogs.path = path.string();
    mDialogs.prompt = Dialogs::Prompt::Open;
    confirmPrompt();
}

void SculptApp::openChosenGrid(std::optional<std::string> grid)
{
    const std::optional<Dialogs::GridChoice> choice = std::exchange(mDialogs.gridChoice, std::nullopt);
    if (choice && grid) startOpen(choice->file, *grid);
}

void SculptApp::confirmPrompt()
{
    const Dialogs::Prompt prompt = mDialogs.prompt;
    const fs::path path = mDialogs.path;
    mDialogs.prompt = Dialogs::Prompt::None;
    try {
        switch (prompt) {
        case Dialogs::Prompt::New:
            setDocument(std::make_unique<Document>(Document::create(mDialogs.newShape)), true);
            mBrush.radius = 10.0 * mDocument->session().field().voxelSize();
            break;
        case Dialogs::Prompt::Open: startOpen(path); break;
        case Dialogs::Prompt::SaveAs: saveTo(path); break;
        case Dialogs::Prompt::ExportMesh: startExport(path); break;
        case Dialogs::Prompt::SaveStrokes:
            mDocument->saveStrokes(path);
            mDialogs.notice = "saved strokes to " + path.string();
            break;
        case Dialogs::Prompt::SmoothModel:
        case Dialogs::Prompt::OffsetModel: startFilter(mDialogs.filter); break;
        case Dialogs::Prompt::Morph: startMorph(path, mDialogs.morph); break;
        case Dialogs::Prompt::Target: startLoadTarget(path); break;
        case Dialogs::Prompt::Import: startImportRead(path); break;
        case Dialogs::Prompt::LoadScene: loadScene(path); break;
        case Dialogs::Prompt::SaveScene:
            if (PrimitivesMode* primitives = mode<PrimitivesMode>()) {
                writeFileAtomically(path, writeScene(primitives->draft().scene()));
                mDialogs.notice = "saved the scene to " + path.string();
            }
            break;
        case Dialogs::Prompt::MorphExport:
            if (MorphMode* morph = mode<MorphMode>()) {
                writeFrames(morph->frames().run().frames, path);
                mDialogs.notice = "wrote " + std::to_string(morph->frames().count()) + " frames to " + path.string();
            }
            break;
        case Dialogs::Prompt::None: break;
        }
    } catch (const InputError& e) {
        showError(e.what());
    }
}

void SculptApp::recover(bool accept)
{
    const std::optional<fs::path> file = mDialogs.recovery;
    mDialogs.recovery.reset();
    if (!file) return;
    if (!accept) {
        std::error_code ec;
        fs::remove(*file, ec);
        return;
    }
    try {
        auto recovered = std::make_unique<Document>(Document::recover(*file, mDocument->path()));
        setDocument(std::move(recovered), false);
        mDialogs.notice = "recovered from " + file->string();
    } catch (const InputError& e) {
        showError(e.what());
    }
}

}  // namespace sculpt::ui
