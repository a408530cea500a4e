#include "core/base/atomic_file.h"
#include "core/base/errors.h"
#include "core/base/text_format.h"
#include "core/field/csg_combine.h"
#include "core/io/mesh_file.h"
#include "core/io/vdb_layout.h"
#include "sculpt/session/morph_run.h"
#include "sculpt/session/scene_bake.h"
#include "sculpt/session/shape_import.h"
#include "ui/app/sculpt_app.h"
#include "ui/window/app_window.h"

#include <algorithm>
#include <chrono>
#include <iostream>
#include <utility>

namespace sculpt::ui {

namespace fs = std::filesystem;

namespace {

void toggle(bool& flag) { flag = !flag; }

constexpr double kIsoStep = 0.01;  // of the samples' range, per PageUp/PageDown

void stepImportIso(ImportDraft& draft, int direction)
{
    const auto [lo, hi] = draft.file().range(draft.options);
    draft.options.iso = std::clamp(draft.iso() + direction * kIsoStep * (hi - lo), lo, hi);
}

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
        if (mMorph) mMorph->togglePlay(mWindow.time());
        break;
    case Command::StepUp:
    case Command::StepDown:
        if (mMorph) mMorph->show(mMorph->shown() + (command == Command::StepUp ? -1 : 1));
        else if (mImport && mImport->file().isScan()) stepImportIso(*mImport, command == Command::StepUp ? 1 : -1);
        break;
    case Command::Import:
        if (busy()) break;
        mDialogs.prompt = Dialogs::Prompt::Import, mDialogs.path.clear(), mDialogs.focusField = true;
        break;
    case Command::ApplyImport: applyImport(); break;
    case Command::AddPrimitive: addPrimitive(SkeletonType::Point); break;
    case Command::RemovePrimitive:
        if (mPrimitives) mPrimitives->removeSelected();
        break;
    case Command::BakePrimitives: bakePrimitives(); break;
    case Command::LoadScene:
        if (mPrimitives || !busy())
            mDialogs.prompt = Dialogs::Prompt::LoadScene, mDialogs.path.clear(), mDialogs.focusField = true;
        break;
    case Command::SaveScene:
        if (mPrimitives)
            mDialogs.prompt = Dialogs::Prompt::SaveScene, mDialogs.path = "scene.json", mDialogs.focusField = true;
        else mDialogs.notice = "no primitives to save: Shift+A adds one";
        break;
    case Command::ToggleXRay: mLook.setXRay(!mLook.xray()); break;
    case Command::MorphKeep:
        if (mMorph) keepMorphFrame();
        break;
    case Command::MorphExport:
        if (mMorph) mDialogs.prompt = Dialogs::Prompt::MorphExport, mDialogs.path = "morph", mDialogs.focusField = true;
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
    }
    mHoverValid = false;
}

bool SculptApp::guardUnsaved(Command command)
{
    if (!mDocument->modified()) return true;
    mDialogs.afterUnsaved = command;
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
    if (*then == Command::Quit) mQuit = true;
    else if (*then == Command::ApplyImport) applyImport();
    else if (*then == Command::New) mDialogs.prompt = Dialogs::Prompt::New;
    else if (*then == Command::Open)
        mDialogs.prompt = Dialogs::Prompt::Open, mDialogs.path.clear(), mDialogs.focusField = true;
    if (discard) mAutosave.discard(mDocument->path());
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
        case Dialogs::Prompt::LoadScene: {
            const Scene scene = readScene(path);  // an error leaves the panel as it was
            if (!mPrimitives) mPrimitives.emplace(mDocument->session().field().grid().transform().copy());
            mPrimitives->load(scene);
            mLook.setXRay(true);
            mDialogs.notice = "loaded " + path.string() + ": Enter bakes it into the model, Esc discards it";
            break;
        }
        case Dialogs::Prompt::SaveScene:
            writeFileAtomically(path, writeScene(mPrimitives->scene()));
            mDialogs.notice = "saved the scene to " + path.string();
            break;
        case Dialogs::Prompt::MorphExport:
            writeFrames(mMorph->run().frames, path);
            mDialogs.notice = "wrote " + std::to_string(mMorph->count()) + " frames to " + path.string();
            break;
        case Dialogs::Prompt::None: break;
        }
    } catch (const InputError& e) {
        showError(e.what());
    }
}

// ---------------------------------------------------------------------------------------------
// Jobs

bool SculptApp::busy()
{
    if (mJob) mDialogs.notice = "wait for " + mJob->label() + " to finish, or press Esc to cancel it";
    else if (mMorph) mDialogs.notice = "the morph's frames are on show: keep one (K) or close them (Esc) first";
    else if (mImport) mDialogs.notice = "an import is open: apply it (Enter) or cancel it (Esc) first";
    else if (mPrimitives)
        mDialogs.notice = "primitives are being placed: bake them (Enter) or discard them (Esc) first";
    return mJob || mMorph || mImport || mPrimitives;
}

void SculptApp::startFilter(const ModelFilter& filter)
{
    if (busy()) return;
    // The job works on its own copy: the document stays as it is until the result lands.
    auto copy = std::make_shared<FieldImage>(mDocument->session().field().deepCopy());
    const std::string source = mDocument->path().empty() ? std::string("the model") : mDocument->path().string();
    const std::string label = filterLabel(filter);
    startJob<FieldImage>(
        label, [copy, filter, source](const Progress& p) { return applyFilter(std::move(*copy), filter, source, p); },
        [this, label](FieldImage result) {
            mDocument->replaceField(std::move(result), label);
            mDialogs.notice = label + " done (Ctrl+Z undoes it)";
        });
}

void SculptApp::startMorph(const fs::path& target, const MorphOptions& options)
{
    if (busy()) return;
    autosaveNow();
    auto copy = std::make_shared<FieldImage>(mDocument->session().field().deepCopy());
    const std::string label = "morph to " + target.filename().string();
    startJob<MorphRun>(
        label, [copy, target, options](const Progress& p) { return morphInto(*copy, target, options, p); },
        [this, label, target](MorphRun run) {
            // The target becomes the loaded one: its ghost shows where the frames go.
            mBrush.target = {target, run.target};
            mGhost.set(run.target.get());
            mMorph.emplace(std::move(run));
            const MorphSummary& s = mMorph->run().summary;
            mDialogs.notice = label + ": " + std::to_string(mMorph->count()) + " frames, " +
                              (s.converged ? "converged" : "NOT converged") + " (Space plays, K keeps a frame)";
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
    // The document (its mesh too) is made on the job's thread; the old one stays if it fails.
    auto warnings = std::make_shared<std::vector<std::string>>();
    startJob<std::unique_ptr<Document>>(
        "open " + path.filename().string(),
        [path, warnings, grid](const Progress& p) {
            return std::make_unique<Document>(Document::open(path, p, warnings.get(), grid));
        },
        [this, path, warnings](std::unique_ptr<Document> document) {
            setDocument(std::move(document), true);
            mRecent.add(path);
            mDialogs.notice = "opened " + path.string();
            if (!warnings->empty()) mDialogs.notice += " (" + warnings->front() + ")";
        });
}

void SculptApp::startExport(const fs::path& path)
{
    if (busy()) return;
    meshFormatOf(path);  // refuse an unknown extension before welding
    // Welded here (the mesher is the UI's), written on the job's thread.
    auto mesh = std::make_shared<TriangleMesh>(mDocument->session().mesher()->weldedMesh());
    startJob<std::size_t>(
        "export " + path.filename().string(),
        [mesh, path](const Progress&) {
            writeMesh(*mesh, path);
            return mesh->triangles.size();
        },
        [this, path](std::size_t triangles) {
            mDialogs.notice = "exported " + path.string() + " (" + std::to_string(triangles) + " triangles)";
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
            mGhost.set(mBrush.target.shape.get());
            mGhost.setShown(true);
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
        "read " + path.filename().string(),
        [path](const Progress&) {
            auto file = std::make_shared<ImportPreview>(path);
            // Sensible defaults for a printable model: the largest piece only, at the file's resolution.
            ImportOptions defaults;
            defaults.largestComponent = true;
            const auto start = std::chrono::steady_clock::now();
            FieldImage first = file->surface(defaults);
            const double ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            return ImportDraft(file, std::move(first), ms, defaults);
        },
        [this](ImportDraft draft) {
            mImport.emplace(std::move(draft));
            mPreview.set(mImport->preview());
            const openvdb::CoordBBox box = mImport->preview()->grid().evalActiveVoxelBoundingBox();
            const auto& xform = mImport->preview()->grid().transform();
            const openvdb::Vec3d lo = xform.indexToWorld(box.min()), hi = xform.indexToWorld(box.max());
            mCamera.frame({lo.x(), lo.y(), lo.z()}, {hi.x(), hi.y(), hi.z()});
            mDialogs.notice = "import " + mImport->file().path().filename().string() + ": Enter applies, Esc cancels";
        });
}

void SculptApp::syncImportPreview()
{
    if (mImport && mImport->refresh()) {
        mPreview.set(mImport->preview());
        if (mPreviewPendingSince < 0.0) mPreviewPendingSince = mLastEventArrival;
    }
    mDisplay.setHidden(mScales.shown() || (mImport && mImport->result == ImportDraft::Result::NewDocument));
}

void SculptApp::applyImport()
{
    if (!mImport || mJob) return;
    ImportDraft& draft = *mImport;
    const bool replaces = draft.result == ImportDraft::Result::NewDocument;
    if (replaces && !guardUnsaved(Command::ApplyImport)) return;
    autosaveNow();
    ImportOptions options = draft.options;
    if (!replaces) options.voxelSize = mDocument->session().field().voxelSize();  // the document's lattice
    const fs::path path = draft.file().path();
    const ImportDraft::Result result = draft.result;
    auto report = std::make_shared<ImportReport>();
    const std::string label = std::string("import ") + (replaces ? "" : importResultName(result) + std::string(" ")) +
                              path.filename().string();
    const auto done = [this, label, report, replaces] {
        mDialogs.notice = label + " done: iso-value " + formatNumber(report->iso) + ", voxel size " +
                          formatNumber(report->voxelSize) + (replaces ? "" : " (Ctrl+Z undoes it)");
        if (!report->warnings.empty()) mDialogs.notice += "; " + report->warnings.front();
    };
    closeImport();
    if (replaces) {  // the new document, its mesh too, made on the job's thread
        startJob<std::unique_ptr<Document>>(
            label,
            [path, options, report](const Progress& p) {
                FieldImage field = importShape(path, options, *report, scaledProgress(p, 0.0, 0.7));
                return std::make_unique<Document>(std::move(field), fs::path(), scaledProgress(p, 0.7, 1.0));
            },
            [this, done](std::unique_ptr<Document> document) {
                setDocument(std::move(document), true);
                done();
            });
        return;
    }
    auto base = std::make_shared<FieldImage>(mDocument->session().field().deepCopy());
    startJob<FieldImage>(
        label,
        [path, options, result, base, report](const Progress& p) {
            const FieldImage shape = importShape(path, options, *report, p);
            combine(*base, shape,
                    result == ImportDraft::Result::Union ? CsgOperation::Union : CsgOperation::Difference);
            return std::move(*base);
        },
        [this, label, done](FieldImage field) {
            mDocument->replaceField(std::move(field), label);
            done();
        });
}

void SculptApp::addPrimitive(SkeletonType type)
{
    if (!mPrimitives && busy()) return;
    if (!mPrimitives) {
        mPrimitives.emplace(mDocument->session().field().grid().transform().copy());
        mLook.setXRay(true);
        mDialogs.notice = "click or drag on the surface to place it; Enter bakes, Esc discards";
    }
    const std::optional<SurfaceHit> hit = pickAt(mMouseX, mMouseY);
    const glm::dvec3 at = hit ? hit->position : mCamera.focalPoint();
    // A soft object crosses iso 0.5 near half its reach: twice the brush gives a blob its size.
    mPrimitives->add(type, {at.x, at.y, at.z}, 2.0 * mBrush.radius);
}

void SculptApp::syncPrimitives()
{
    if (!mPrimitives) return;
    const bool changed = mPrimitives->refresh();
    if (changed) mPrimitivePreview.set(mPrimitives->preview());
    // The skeletons' geometry is rebuilt only when the scene or the selection changed.
    if (changed || mPrimitives->selected != mSkeletonsSelected)
        mSkeletons.show(mPrimitives->primitives, mPrimitives->selected);
    mSkeletonsSelected = mPrimitives->selected;
}

void SculptApp::bakePrimitives()
{
    if (!mPrimitives || mJob) return;
    try {
        // Through the scene file's text: the bake is then `sculpt build` of the scene Save writes.
        const Scene scene = parseScene(writeScene(mPrimitives->scene()), "the scene");
        auto base = std::make_shared<FieldImage>(mDocument->session().field().deepCopy());
        const std::string label = "bake " + std::to_string(scene.primitives.primitives().size()) + " primitives";
        closePrimitives();
        startJob<FieldImage>(
            label,
            [base, scene](const Progress& p) {
                return bakeScene(std::move(*base), scene, "the scene", "the model", p);
            },
            [this, label](FieldImage result) {
                mDocument->replaceField(std::move(result), label);
                mDialogs.notice = label + " done (Ctrl+Z undoes it)";
            });
    } catch (const InputError& e) {
        showError(e.what());
    }
}

void SculptApp::closePrimitives()
{
    mPrimitives.reset();
    mPrimitivePreview.set(nullptr);
    mSkeletons.show({}, -1);
    mLook.setXRay(false);
    if (mDrag == Drag::Primitive) mDrag = Drag::None;
    mHoverValid = false;
}

void SculptApp::closeImport()
{
    mImport.reset();
    mPreview.set(nullptr);
    mHoverValid = false;
}

void SculptApp::keepMorphFrame()
{
    try {
        mDocument->replaceField(mMorph->shownField().deepCopy(), "morph frame " + std::to_string(mMorph->shown()));
        mDialogs.notice = "kept morph frame " + std::to_string(mMorph->shown()) + " (Ctrl+Z undoes it)";
        closeMorph();
    } catch (const InputError& e) {
        showError(e.what());
    }
}

void SculptApp::closeMorph()
{
    mMorph.reset();
    mHoverValid = false;
}

void SculptApp::cancelJob()
{
    if (mJob) mJob->cancel();
}

void SculptApp::pollJob()
{
    if (!mJob || !mJob->finished()) return;
    const std::unique_ptr<BackgroundJob> job = std::move(mJob);
    const std::function<void()> land = std::move(mLandJob);
    if (job->succeeded()) {
        try {
            land();
        } catch (const InputError& e) {
            showError(e.what());
        }
        mLastJob = "finished";
    } else if (job->cancelled()) {
        mDialogs.notice = job->label() + " cancelled: the model is as it was";
        mLastJob = "cancelled";
    } else {
        showError(job->error());
        mLastJob = "failed";
    }
    mHoverValid = false;
    mLastInput = mWindow.time();  // show the notice
}

bool SculptApp::holdsReplay() const { return mJob || (mMorph && mMorph->playing()); }

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
