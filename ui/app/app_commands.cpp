// SculptApp: what each command does, and the dialogs' outcomes.

#include "core/base/atomic_file.h"
#include "core/base/errors.h"
#include "core/primitives/scene_file.h"
#include "sculpt/session/frame_files.h"
#include "sculpt/session/morph_run.h"
#include "sculpt/session/tracked_export.h"
#include "ui/app/sculpt_app.h"
#include "ui/modes/morph_mode.h"
#include "ui/modes/primitives_mode.h"
#include "ui/window/window.h"

#include <algorithm>
#include <iostream>
#include <utility>

namespace sculpt::ui {

namespace fs = std::filesystem;

void SculptApp::execute(Command command)
{
    if (strokeActive()) return;  // nothing interrupts a stroke
    const std::string blocked = whyNot(command);
    if (blocked.empty()) mCommands.row(command).run();
    else mDialogs.notice = blocked;
}

std::string SculptApp::whyNot(Command command) const { return mCommands.whyNot(command); }

bool Dialogs::confirmable() const
{
    if (prompt == Prompt::None || recovery || gridChoice || afterUnsaved) return false;
    const bool asksForPath = prompt != Prompt::New && prompt != Prompt::SmoothModel && prompt != Prompt::OffsetModel &&
                             prompt != Prompt::HollowModel && prompt != Prompt::RemoveIslands;
    return !asksForPath || !path.empty();
}

void SculptApp::openPrompt(Dialogs::Prompt prompt, std::string path)
{
    mDialogs.prompt = prompt;
    mDialogs.path = std::move(path);
    mDialogs.focusField = true;
}

std::string SculptApp::besideDocument(const char* extension, const char* fallback) const
{
    if (mDocument->path().empty()) return fallback;
    return fs::path(mDocument->path()).replace_extension(extension).string();
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
    openPrompt(Dialogs::Prompt::Open, path.string());
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
        case Dialogs::Prompt::OffsetModel:
        case Dialogs::Prompt::HollowModel:
        case Dialogs::Prompt::RemoveIslands: startFilter(mDialogs.filter); break;
        case Dialogs::Prompt::Morph: startMorph(path, mDialogs.morph, mDialogs.morphTracked); break;
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
                const MorphRun& run = morph->frames().run();
                writeFrames(run.frames, path);
                mDialogs.notice = "wrote " + std::to_string(morph->frames().count()) + " frames to " + path.string();
                if (run.tracking) {
                    prepareDirectory(path / "tracked");
                    writeTrackedSequence(run.tracking->sequence(), path / "tracked");
                    mDialogs.notice += " and the tracked mesh (" +
                                       std::to_string(run.tracking->sequence().segments().size()) +
                                       " segments: .ply, .pc2, .glb, .usda) to " + (path / "tracked").string();
                }
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

void SculptApp::editMask(MaskOperation operation)
{
    if (busy()) return;
    if (mDocument->editMask(operation)) return;
    notify(mDocument->session().field().mask()
               ? "the mask did not change"
               : "nothing is masked: paint a mask first (M), or invert to mask everything");
}

}  // namespace sculpt::ui
