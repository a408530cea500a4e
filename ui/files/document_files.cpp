// SPDX-License-Identifier: Apache-2.0
#include "ui/files/document_files.h"

#include "core/base/errors.h"
#include "core/io/vdb_layout.h"
#include "sculpt/session/label_export.h"
#include "sculpt/session/piece_meshes.h"
#include "ui/workspace/workspace.h"

#include <nlohmann/json.hpp>

#include <iostream>
#include <utility>

namespace sculpt::ui {

namespace fs = std::filesystem;

DocumentFiles::DocumentFiles(Workspace& work, const fs::path& stateDir) : mWork(work), mRecent(stateDir) {}

void DocumentFiles::openAtStart(const fs::path& path, const std::string& grid)
{
    mRecovery = mWork.autosave().pending(path);  // an untitled document's too
    if (!path.empty()) mRecent.add(path);
    if (!path.empty() && !mRecovery) {
        mOpeningAtStart = true;
        return openInJob(path, grid);
    }
    // Offering its recovery asks for the document as it is.
    const NewShape ball;
    mWork.replace(
        std::make_unique<Document>(path.empty() ? Document::create(ball) : Document::open(path, {}, nullptr, grid)),
        true);
}

DocumentFiles::Start DocumentFiles::followStart(JobRunner::Ending ending, const std::string& error, bool shown)
{
    if (!mOpeningAtStart) return Start::None;
    switch (ending) {
    case JobRunner::Ending::Running:  // the job is done when its chunks all are
        if (mWork.jobs().running() || !shown) return Start::None;
        mOpeningAtStart = false;
        return Start::Shown;
    case JobRunner::Ending::Finished: return Start::Landed;  // its chunks fill in from now
    case JobRunner::Ending::Cancelled:
        mOpeningAtStart = false;
        mWork.replace(std::make_unique<Document>(Document::create(NewShape{})), true);
        mWork.notices().say("opening cancelled: a new clay ball instead (File > Open to try again)");
        return Start::None;
    case JobRunner::Ending::Failed: break;
    }
    throw InputError(error);  // as if it failed before the window
}

void DocumentFiles::open(const fs::path& path, const std::string& grid)
{
    if (mWork.busy()) return;
    mWork.autosaveNow();
    if (grid.empty()) {
        // A file of several level sets and none to take by default: ask which (a damaged
        // file is left for the job to report).
        try {
            const VdbLayout layout = scanVdbLayout(path);
            if (!defaultGrid(layout) && levelSetNames(layout).size() > 1) {
                mGridChoice = GridChoice{path, levelSetNames(layout)};
                return;
            }
        } catch (const InputError&) {}
    }
    openInJob(path, grid);
}

void DocumentFiles::openInJob(const fs::path& path, const std::string& grid)
{
    // The document (its mesh too) is made on the job's thread; the old one stays if it fails.
    auto warnings = std::make_shared<std::vector<std::string>>();
    mWork.startDocument(
        "open " + path.filename().string(),
        [path, warnings, grid](const Progress& p, const Workspace::FieldReady& ready) {
            return std::make_unique<Document>(Document::open(path, p, warnings.get(), grid, ready));
        },
        [this, path, warnings] {
            mRecent.add(path);
            return "opened " + path.string() + (warnings->empty() ? "" : " (" + warnings->front() + ")");
        });
}

void DocumentFiles::saveTo(const fs::path& path)
{
    try {
        Document& document = mWork.document();
        const fs::path previous = document.path();
        document.saveAs(path);
        mWork.autosave().discard(previous);
        mWork.autosave().discard(path);
        mRecent.add(path);
        mWork.notices().say("saved " + path.string());
        std::cout << "sculpt-ui: " << mWork.notices().notice() << std::endl;
    } catch (const InputError& e) {
        mWork.notices().fail(e.what());
    }
}

void DocumentFiles::exportMesh(const fs::path& path)
{
    if (mWork.busy()) return;
    // Welded here (the meshers are the UI's), written on the job's thread.
    auto meshes = std::make_shared<std::vector<PieceMesh>>(mWork.document().meshesToExport(path));
    mWork.startJob<std::vector<std::string>>(
        "export " + path.filename().string(),
        [meshes, path](const Progress&) { return linesOf(writePieceMeshes(*meshes, path)); },
        [this](std::vector<std::string> lines) {
            mWork.notices().say(lines.size() == 1 ? lines.front()
                                                  : "exported " + std::to_string(lines.size()) +
                                                        " pieces: " + lines.front() + ", ...");
            for (const std::string& line : lines) std::cout << "sculpt-ui: " << line << std::endl;
        });
}

void DocumentFiles::exportLabels(const fs::path& path)
{
    if (mWork.busy()) return;
    const Document& document = mWork.document();
    const ScanLattice lattice = labelLattice({}, document.keptScan(), document.title());
    auto pieces = std::make_shared<std::vector<Piece>>(document.piecesAsFiled());  // sharing the grids
    mWork.startJob<std::vector<std::string>>(
        "export " + path.filename().string(),
        [pieces, lattice, path](const Progress& progress) {
            return describeLabels(sculpt::exportLabels(*pieces, lattice, path, progress));
        },
        [this, path](std::vector<std::string> lines) {
            mWork.notices().say("exported " + path.filename().string() + ": " + lines.front());
            for (const std::string& line : lines) std::cout << "sculpt-ui: " << line << std::endl;
        });
}

std::string DocumentFiles::besideDocument(const char* extension, const char* fallback) const
{
    const fs::path& path = mWork.document().path();
    return path.empty() ? fallback : fs::path(path).replace_extension(extension).string();
}

bool DocumentFiles::guardUnsaved(Command again)
{
    if (!mWork.document().modified() || mUnsavedAnswered) return true;
    mAfterUnsaved = again;
    return false;
}

void DocumentFiles::answerUnsaved(bool save, bool discard, const std::function<void(Command)>& execute)
{
    const std::optional<Command> then = std::exchange(mAfterUnsaved, std::nullopt);
    if (!then || (!save && !discard)) return;  // cancelled
    const fs::path path = mWork.document().path();
    if (save) {
        if (path.empty()) return execute(Command::SaveAs);  // the user names it, then repeats the command
        saveTo(path);
        if (mWork.document().modified()) return;  // the save failed: the error is shown
    }
    if (discard) mWork.autosave().discard(path);
    mUnsavedAnswered = true;  // the command runs as if there were nothing to save, once
    execute(*then);
    mUnsavedAnswered = false;
}

void DocumentFiles::recover(bool accept)
{
    const std::optional<fs::path> file = std::exchange(mRecovery, std::nullopt);
    if (!file) return;
    if (!accept) {
        std::error_code ec;
        fs::remove(*file, ec);
        return;
    }
    try {
        mWork.replace(std::make_unique<Document>(Document::recover(*file, mWork.document().path())), false);
        mWork.notices().say("recovered from " + file->string());
    } catch (const InputError& e) {
        mWork.notices().fail(e.what());
    }
}

void DocumentFiles::chooseGrid(std::optional<std::string> grid)
{
    const std::optional<GridChoice> choice = std::exchange(mGridChoice, std::nullopt);
    if (choice && grid) open(choice->file, *grid);
}

void DocumentFiles::report(nlohmann::json& out) const
{
    out["recovery_offered"] = mRecovery.has_value();
    out["asking_unsaved"] = mAfterUnsaved.has_value();
}

}  // namespace sculpt::ui
