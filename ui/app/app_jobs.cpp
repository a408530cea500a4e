// SculptApp: the work that runs off the UI thread (whole-model edits, documents opened or
// imported, exports, targets, morphs) and how its result lands.

#include "core/base/errors.h"
#include "core/base/text_format.h"
#include "core/io/mesh_file.h"
#include "core/io/vdb_layout.h"
#include "core/solids/islands.h"
#include "sculpt/session/morph_run.h"
#include "sculpt/session/shape_import.h"
#include "ui/app/sculpt_app.h"
#include "ui/document/import_draft.h"
#include "ui/modes/import_mode.h"
#include "ui/modes/morph_mode.h"
#include "ui/view/block_polydata.h"
#include "ui/window/window.h"

#include <chrono>
#include <iostream>

namespace sculpt::ui {

namespace fs = std::filesystem;

namespace {

/// The scan or mesh at `path` read for the Import panel, with a first preview.
ImportDraft readForImport(const fs::path& path)
{
    auto file = std::make_shared<ImportPreview>(path);
    // Sensible defaults for a printable model: the largest piece only, at the file's resolution.
    ImportOptions defaults;
    defaults.largestComponent = true;
    const auto start = std::chrono::steady_clock::now();
    FieldImage first = file->surface(defaults);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return ImportDraft(file, std::move(first), ms, defaults);
}

}  // namespace

std::string SculptApp::waitReason() const
{
    if (mJobs.running()) return "wait for " + mJobs.job()->label() + " to finish, or press Esc to cancel it";
    if (const std::string gesture = mTools.current().waitReason(); !gesture.empty()) return gesture;
    return mMode ? mMode->waitNotice() : std::string();
}

bool SculptApp::busy()
{
    const std::string reason = waitReason();
    if (!reason.empty()) mDialogs.notice = reason;
    return !reason.empty();
}

bool SculptApp::holdsReplay() const { return mJobs.running() || (mMode && mMode->holdsReplay()); }

void SculptApp::pollJob()
{
    const JobRunner::Outcome outcome = mJobs.poll();
    switch (outcome.ending) {
    case JobRunner::Ending::Running: return;
    case JobRunner::Ending::Finished: mLastJob = "finished"; break;
    case JobRunner::Ending::Cancelled:
        mDialogs.notice = outcome.label + " cancelled: the model is as it was";
        mLastJob = "cancelled";
        break;
    case JobRunner::Ending::Failed:
        showError(outcome.error);
        mLastJob = "failed";
        break;
    }
    mLastInput = mWindow.time();  // show the notice
    mOpenPreview.reset();
    mView.redrawPieces();  // a push that did not land leaves its piece where it was
    if (outcome.ending != JobRunner::Ending::Finished) mView.display().dropPreview();
    if (mOpeningAtStart) followStartupOpen(outcome.ending, outcome.error);
}

void SculptApp::showOpenPreview()
{
    std::optional<OpenPreview::Surface> preview = mOpenPreview ? mOpenPreview->take() : std::nullopt;
    if (!preview) return;
    mView.display().showPreview(preview->mesh, *preview->xform);
    ++mPreviewsShown;
    if (!preview->mesh.positions.empty()) {
        const auto [lo, hi] = boundsOf(preview->mesh.positions.data(), preview->mesh.positions.size());
        mView.camera().frame(lo, hi);
    }
    if (mOpeningAtStart) std::cout << "sculpt-ui: preview in " << formatSeconds(mWindow.time()) << " s" << std::endl;
}

void SculptApp::followStartupOpen(JobRunner::Ending ending, const std::string& error)
{
    switch (ending) {
    case JobRunner::Ending::Running:  // the job is done when its chunks all are
        if (mJobs.running() || mView.display().pendingChunks() > 0) return;
        std::cout << "sculpt-ui: full detail in " << formatSeconds(mWindow.time()) << " s" << std::endl;
        break;
    case JobRunner::Ending::Finished:
        mBrush.radius = 10.0 * mDocument->session().field().voxelSize();
        return;  // its chunks fill in from now
    case JobRunner::Ending::Cancelled:
        setDocument(std::make_unique<Document>(Document::create(NewShape{})), true);
        mDialogs.notice = "opening cancelled: a new clay ball instead (File > Open to try again)";
        break;
    case JobRunner::Ending::Failed: throw InputError(error);  // as if it failed before the window
    }
    mOpeningAtStart = false;
}

void SculptApp::startEdit(ModelEdit edit)
{
    // The job works on its own copy: the document stays as it is until the result lands.
    auto copy = std::make_shared<FieldImage>(mDocument->session().field().deepCopy());
    const std::string label = edit.label;
    startJob<FieldImage>(
        label, [copy, work = std::move(edit.work)](const Progress& p) { return work(std::move(*copy), p); },
        [this, label, summary = std::move(edit.summary), scripted = std::move(edit.scripted),
         takes = edit.takes](FieldImage result) {
            if (takes == ModelEdit::Takes::Mask) mDocument->replaceMask(result.maskPtr(), label, *scripted);
            else mDocument->replaceField(std::move(result), label, scripted);
            const std::string extra = summary ? summary() : std::string();
            mDialogs.notice = label + " done" + (extra.empty() ? "" : ": " + extra) + " (Ctrl+Z undoes it)";
        });
}

void SculptApp::startDocument(std::string label, DocumentMaker make, std::function<std::string()> landed)
{
    auto preview = mOpenPreview = std::make_shared<OpenPreview>(mOptions.previewTriangles);
    startJob<std::unique_ptr<Document>>(
        std::move(label),
        [make = std::move(make), preview](const Progress& p) {
            return make(p, [&](const FieldImage& f) { preview->offer(f); });
        },
        [this, landed = std::move(landed)](std::unique_ptr<Document> document) {
            // A preview was framed: the view stays as the user left it.
            setDocument(std::move(document), !mView.display().showsPreview());
            mDialogs.notice = landed();
        });
}

void SculptApp::startFilter(const ModelFilter& filter)
{
    if (busy()) return;
    const std::string source = mDocument->path().empty() ? std::string("the model") : mDocument->path().string();
    startEdit({filterLabel(filter),
               [filter, source](FieldImage model, const Progress& p) {
                   return applyFilter(std::move(model), filter, source, p);
               },
               {}});
}

void SculptApp::editIslandUnderPointer(bool keep)
{
    if (busy()) return;
    const std::optional<SurfaceHit> hit = pickAt(mPointer.x(), mPointer.y());
    if (!hit) return notify(std::string("point at the island to ") + (keep ? "keep" : "delete") + " first");
    const openvdb::Vec3d at(hit->position.x, hit->position.y, hit->position.z);
    const double reach = 2.0 * mDocument->session().field().voxelSize();
    startEdit({keep ? "keep island" : "delete island",
               [at, reach, keep](FieldImage model, const Progress&) {
                   const std::vector<Island> islands = findIslands(model);
                   const int index = islandAt(islands, at, reach);
                   if (index < 0) throw InputError("no island under the pointer");
                   keepOrRemoveIsland(model, islands, std::size_t(index), keep);
                   refuseEmptyResult(model, "the model", keep ? "keep island" : "delete island");
                   return model;
               },
               {}});
}

void SculptApp::drillDrainHoleUnderPointer()
{
    if (busy()) return;
    const std::optional<SurfaceHit> hit = pickAt(mPointer.x(), mPointer.y());
    if (!hit) return notify("point at the wall to drill the drain hole through first");
    const FieldImage& field = mDocument->session().field();
    const openvdb::Vec3d at(hit->position.x, hit->position.y, hit->position.z);
    const openvdb::Vec3d normal(hit->normal.x, hit->normal.y, hit->normal.z);
    const double radius = mDialogs.filter.drainRadiusWorld;
    const double farthest = std::max(mDocument->session().modelSize(), 4.0 * field.voxelSize());
    const std::optional<DrainHole> hole = drainHoleAt(field, at, normal, radius, farthest);
    if (!hole) return notify("no hollow behind the wall here: Filters > Hollow makes one");
    mDocument->drillHoles({*hole});
    mDialogs.notice = "drain hole drilled (Ctrl+Z undoes it)";
}

void SculptApp::startMorph(const fs::path& target, const MorphOptions& options, bool tracked)
{
    if (busy()) return;
    autosaveNow();
    auto copy = std::make_shared<FieldImage>(mDocument->session().field().deepCopy());
    const std::string label = "morph to " + target.filename().string();
    startJob<MorphRun>(
        label,
        [copy, target, options, tracked](const Progress& p) { return morphInto(*copy, target, options, p, tracked); },
        [this, label, target](MorphRun run) {
            // The target becomes the loaded one: its ghost shows where the frames go.
            mBrush.target = {target, run.target};
            mView.ghost().set(run.target.get());
            openMode(std::make_unique<MorphMode>(mView.viewport().renderer(), label, std::move(run)));
        });
}

void SculptApp::startOpen(const fs::path& path, const std::string& grid)
{
    if (busy()) return;
    autosaveNow();
    if (grid.empty()) {
        // A file of several level sets and none to take by default: ask which (a damaged
        // file is left for the job to report).
        try {
            const VdbLayout layout = scanVdbLayout(path);
            if (!defaultGrid(layout) && levelSetNames(layout).size() > 1) {
                mDialogs.gridChoice = Dialogs::GridChoice{path, levelSetNames(layout)};
                return;
            }
        } catch (const InputError&) {}
    }
    openInJob(path, grid);
}

void SculptApp::openInJob(const fs::path& path, const std::string& grid)
{
    // The document (its mesh too) is made on the job's thread; the old one stays if it fails.
    auto warnings = std::make_shared<std::vector<std::string>>();
    startDocument(
        "open " + path.filename().string(),
        [path, warnings, grid](const Progress& p, const FieldReady& ready) {
            return std::make_unique<Document>(Document::open(path, p, warnings.get(), grid, ready));
        },
        [this, path, warnings] {
            mRecent.add(path);
            return "opened " + path.string() + (warnings->empty() ? "" : " (" + warnings->front() + ")");
        });
}

void SculptApp::startExport(const fs::path& path)
{
    if (busy()) return;
    // Welded here (the meshers are the UI's), written on the job's thread.
    auto meshes = std::make_shared<std::vector<PieceMesh>>(mDocument->meshesToExport(path));
    startJob<std::vector<std::string>>(
        "export " + path.filename().string(),
        [meshes, path](const Progress&) { return writePieceMeshes(*meshes, path); },
        [this](std::vector<std::string> lines) {
            mDialogs.notice = lines.size() == 1
                                  ? lines.front()
                                  : "exported " + std::to_string(lines.size()) + " pieces: " + lines.front() + ", ...";
            for (const std::string& line : lines) std::cout << "sculpt-ui: " << line << std::endl;
        });
}

void SculptApp::startLoadTarget(const fs::path& path)
{
    if (busy()) return;
    autosaveNow();
    auto warnings = std::make_shared<std::vector<std::string>>();
    startJob<FieldImage>(
        "load target " + path.filename().string(),
        [path, warnings](const Progress& p) { return loadShape(path, std::nullopt, *warnings, p); },
        [this, path, warnings](FieldImage shape) {
            mBrush.target = {path, std::make_shared<const FieldImage>(std::move(shape))};
            mView.ghost().set(mBrush.target.shape.get());
            mView.ghost().setShown(true);
            mDialogs.notice =
                "target " + path.filename().string() + " loaded: O is the follow brush, H hides the ghost";
            if (!warnings->empty()) mDialogs.notice += " (" + warnings->front() + ")";
        });
}

void SculptApp::startImportRead(const fs::path& path)
{
    if (busy()) return;
    autosaveNow();
    startJob<ImportDraft>(
        "read " + path.filename().string(), [path](const Progress&) { return readForImport(path); },
        [this](ImportDraft draft) {
            const openvdb::CoordBBox box = draft.preview()->grid().evalActiveVoxelBoundingBox();
            const auto& xform = draft.preview()->grid().transform();
            const openvdb::Vec3d lo = xform.indexToWorld(box.min()), hi = xform.indexToWorld(box.max());
            openMode(std::make_unique<ImportMode>(mView.viewport().renderer(), std::move(draft)));
            mView.camera().frame({lo.x(), lo.y(), lo.z()}, {hi.x(), hi.y(), hi.z()});
        });
}

}  // namespace sculpt::ui
