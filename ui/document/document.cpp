#include "ui/document/document.h"

#include "core/base/atomic_file.h"
#include "core/base/errors.h"
#include "core/base/text_format.h"
#include "core/io/mesh_file.h"
#include "core/io/vdb_file.h"
#include "core/primitives/analytic_shapes.h"

#include <cmath>

namespace sculpt::ui {

namespace {

/// A new document's voxels along its longest side: beyond this, File > New refuses.
constexpr double kMaxVoxelsAcross = 2048.0;

std::string strokeLabel(const Stroke& stroke, std::size_t stamps)
{
    return std::string(brushToolName(stroke.brush.tool)) + "  r " + formatNumber(stroke.brush.radiusWorld) + ", " +
           std::to_string(stamps) + " stamps";
}

}  // namespace

Document::Document(FieldImage field, std::filesystem::path path, const Progress& meshing)
    : mSession(std::move(field), /*liveMesh=*/true, UndoHistory::kDefaultBudgetBytes, meshing), mPath(std::move(path))
{}

Document Document::create(const NewShape& shape)
{
    if (!(shape.voxelSize > 0.0 && std::isfinite(shape.voxelSize))) {
        throw InputError("New: the voxel size must be a positive number");
    }
    if (!(shape.size > 0.0 && std::isfinite(shape.size))) throw InputError("New: the size must be a positive number");
    const double across = 2.0 * shape.size * (shape.shape == 2 ? 4.0 / 3.0 : 1.0) / shape.voxelSize;
    if (across > kMaxVoxelsAcross) {
        throw InputError("New: " + formatNumber(std::round(across)) + " voxels across is more than the limit of " +
                         formatNumber(kMaxVoxelsAcross) + ": choose a coarser voxel size");
    }
    if (across < 8.0) throw InputError("New: the shape is under 8 voxels across: choose a finer voxel size");
    switch (shape.shape) {
    case 1: return Document(makeBox(shape.size, shape.voxelSize));
    case 2: return Document(makeTorus(shape.size, shape.size / 3.0, shape.voxelSize));
    default: return Document(makeSphere(shape.size, shape.voxelSize));
    }
}

Document Document::open(const std::filesystem::path& path, const Progress& progress, std::vector<std::string>* warnings,
                        const std::string& grid, const std::function<void(const FieldImage&)>& beforeMeshing)
{
    VdbDocument file = readVdbDocument(path, grid);
    report(progress, 0.3);  // reading is quick next to meshing
    if (beforeMeshing) beforeMeshing(file.field);
    Document document(std::move(file.field), path, scaledProgress(progress, 0.3, 1.0));
    document.mCompanions = std::move(file.companions);
    if (warnings) *warnings = std::move(file.warnings);
    return document;
}

Document Document::recover(const std::filesystem::path& recoveryFile, std::filesystem::path documentPath)
{
    Document document = open(recoveryFile);
    document.mPath = std::move(documentPath);
    document.markUnsaved();
    return document;
}

void Document::save() { saveAs(mPath); }

void Document::saveAs(const std::filesystem::path& path)
{
    writeFieldImage(mSession.field(), path, mCompanions);
    mPath = path;
    mSavedState = mState;
}

void Document::exportMesh(const std::filesystem::path& path) const
{
    meshFormatOf(path);  // refuse an unknown extension before welding
    writeMesh(mSession.mesher()->weldedMesh(), path);
}

void Document::saveStrokes(const std::filesystem::path& path) const
{
    if (!mUnscripted.empty()) {
        throw InputError(path.string() + ": the history holds a whole-model edit (" + mUnscripted +
                         "), which a stroke script cannot replay; save the document instead");
    }
    writeFileAtomically(path, writeStrokeScript(mLog));
}

std::string Document::title() const
{
    const std::string name = mPath.empty() ? "untitled" : mPath.filename().string();
    return name + (modified() ? " *" : "");
}

void Document::beginStroke(const Stroke& settings, StrokeSources sources)
{
    mSession.beginStroke(settings);
    mPendingSources = std::move(sources);
}

SculptSession::StrokeReport Document::extendStroke(const StrokeSample& sample) { return mSession.extendStroke(sample); }

void Document::endStroke()
{
    SculptSession::FinishedStroke done = mSession.endStroke();
    ++mRevision;
    if (done.report.leavesChanged == 0) return;  // the history ignores a stroke that changed nothing
    recordStep(strokeLabel(done.stroke, done.report.stamps));
    mLog.events.push_back({ScriptEvent::Kind::Stroke, std::move(done.stroke), std::move(mPendingSources)});
}

void Document::replaceField(FieldImage result, const std::string& label)
{
    mSession.replaceField(std::move(result));
    ++mRevision;
    recordStep(label);
    if (mUnscripted.empty()) mUnscripted = label;
}

void Document::recordStep(const std::string& label)
{
    mUndoLabels.push_back(label);
    mRedoLabels.clear();
    mRedoStates.clear();
    mUndoStates.push_back(mState);
    mState = mNextState++;
    const std::size_t kept = mSession.history().undoCount();  // the oldest may be forgotten (budget)
    while (mUndoLabels.size() > kept) {
        mUndoLabels.erase(mUndoLabels.begin());
        mUndoStates.erase(mUndoStates.begin());
    }
}

bool Document::undo()
{
    if (!mSession.undo()) return false;
    ++mRevision;
    mRedoLabels.insert(mRedoLabels.begin(), mUndoLabels.back());
    mUndoLabels.pop_back();
    mRedoStates.push_back(mState);
    mState = mUndoStates.back();
    mUndoStates.pop_back();
    mLog.events.push_back({ScriptEvent::Kind::Undo, {}, {}});
    return true;
}

bool Document::redo()
{
    if (!mSession.redo()) return false;
    ++mRevision;
    mUndoLabels.push_back(mRedoLabels.front());
    mRedoLabels.erase(mRedoLabels.begin());
    mUndoStates.push_back(mState);
    mState = mRedoStates.back();
    mRedoStates.pop_back();
    mLog.events.push_back({ScriptEvent::Kind::Redo, {}, {}});
    return true;
}

}  // namespace sculpt::ui
