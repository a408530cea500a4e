// SPDX-License-Identifier: Apache-2.0
#include "sculpt/session/document.h"

#include "core/base/atomic_file.h"
#include "core/base/errors.h"
#include "core/base/text_format.h"
#include "core/io/mesh_file.h"
#include "core/io/vdb_file.h"
#include "core/primitives/analytic_shapes.h"
#include "core/scan/kept_scan.h"
#include "sculpt/session/piece_meshes.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace sculpt {

namespace {

/// A new document's voxels along its longest side: beyond this, File > New refuses.
constexpr double kMaxVoxelsAcross = 2048.0;

std::string strokeLabel(const Stroke& stroke, std::size_t stamps)
{
    return std::string(brushToolName(stroke.brush.tool)) + "  r " + formatNumber(stroke.brush.radiusWorld) + ", " +
           std::to_string(stamps) + " stamps";
}

}  // namespace

DocumentPiece makeDocumentPiece(Piece piece, const Progress& meshing, PieceMeshes meshes)
{
    PieceLook look = piece;
    return {std::move(look), std::make_shared<SculptSession>(std::move(piece.field), meshes == PieceMeshes::Live,
                                                             UndoHistory::kDefaultBudgetBytes, meshing)};
}

Document::Document(FieldImage field, std::filesystem::path path, const Progress& meshing, PieceMeshes meshes)
    : Document(std::vector<Piece>{{{field.grid().getName().empty() ? "surface" : field.grid().getName()}, field}},
               std::move(path), meshing, meshes)
{}

Document::Document(std::vector<Piece> pieces, std::filesystem::path path, const Progress& meshing, PieceMeshes meshes)
    : mMeshes(meshes), mPath(std::move(path))
{
    // Progress in proportion to each piece's voxels: meshing time follows them.
    double total = 0.0, done = 0.0;
    for (const Piece& piece : pieces) total += double(piece.field.grid().activeVoxelCount()) + 1.0;
    for (Piece& piece : pieces) {
        const double share = (double(piece.field.grid().activeVoxelCount()) + 1.0) / total;
        mPieces.push_back(makeDocumentPiece(std::move(piece), scaledProgress(meshing, done, done + share), meshes));
        done += share;
    }
}

Document Document::create(const NewShape& shape)
{
    if (!(shape.voxelSize > 0.0 && std::isfinite(shape.voxelSize))) {
        throw InputError("New: the voxel size must be a positive number");
    }
    if (!(shape.size > 0.0 && std::isfinite(shape.size))) throw InputError("New: the size must be a positive number");
    const double across = 2.0 * shape.size * (shape.kind == NewShape::Kind::Torus ? 4.0 / 3.0 : 1.0) / shape.voxelSize;
    if (across > kMaxVoxelsAcross) {
        throw InputError("New: " + formatNumber(std::round(across)) + " voxels across is more than the limit of " +
                         formatNumber(kMaxVoxelsAcross) + ": choose a coarser voxel size");
    }
    if (across < 8.0) throw InputError("New: the shape is under 8 voxels across: choose a finer voxel size");
    switch (shape.kind) {
    case NewShape::Kind::Box: return Document(makeBox(shape.size, shape.voxelSize));
    case NewShape::Kind::Torus: return Document(makeTorus(shape.size, shape.size / 3.0, shape.voxelSize));
    case NewShape::Kind::Sphere: break;
    }
    return Document(makeSphere(shape.size, shape.voxelSize));
}

Document Document::open(const std::filesystem::path& path, const Progress& progress, std::vector<std::string>* warnings,
                        const std::string& grid, const std::function<void(const FieldImage&)>& beforeMeshing)
{
    VdbPieces file = readVdbPieces(path, grid);
    report(progress, 0.3);  // reading is quick next to meshing
    if (beforeMeshing) beforeMeshing(file.pieces.front().field);
    Document document(std::move(file.pieces), path, scaledProgress(progress, 0.3, 1.0));
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
    writeCopy(path);
    mPath = path;
    mSavedState = mState;
}

void Document::writeCopy(const std::filesystem::path& path) const
{
    writeVdbPieces(piecesAsFiled(), path, mCompanions);
}

openvdb::FloatGrid::ConstPtr Document::keptScan() const { return findKeptScan(mCompanions.grids); }

void Document::keepScan(openvdb::FloatGrid::Ptr scan)
{
    auto& grids = mCompanions.grids;
    grids.erase(std::remove_if(grids.begin(), grids.end(), [](const auto& grid) { return grid && isKeptScan(*grid); }),
                grids.end());
    if (scan) grids.push_back(std::move(scan));
}

std::vector<Piece> Document::piecesAsFiled() const
{
    std::vector<Piece> filed;
    for (const DocumentPiece& piece : mPieces) filed.push_back({piece.look, piece.session->field()});
    return filed;
}

std::vector<PieceMesh> Document::meshesToExport(const std::filesystem::path& path) const
{
    meshFormatOf(path);  // refuse an unknown extension before welding
    std::vector<PieceMesh> meshes;
    for (const DocumentPiece& piece : mPieces)
        if (piece.look.visible || mPieces.size() == 1)
            meshes.push_back({piece.look.name, placedMesh(piece.session->mesher()->weldedMesh(), piece.look.placement),
                              piece.look.colour, piece.session->field().units()});
    if (meshes.empty()) throw InputError(path.string() + ": every piece is hidden: nothing to export");
    return meshes;
}

std::vector<std::string> Document::exportMesh(const std::filesystem::path& path) const
{
    return linesOf(writePieceMeshes(meshesToExport(path), path));
}

void Document::saveStrokes(const std::filesystem::path& path) const
{
    if (!mUnscripted.empty()) {
        throw InputError(path.string() + ": the history holds an edit a stroke script cannot replay (" + mUnscripted +
                         "); save the document instead");
    }
    writeFileAtomically(path, writeStrokeScript(mLog));
}

std::string Document::title() const
{
    const std::string name = mPath.empty() ? "untitled" : mPath.filename().string();
    return name + (modified() ? " *" : "");
}

void Document::setActivePiece(std::size_t index)
{
    if (index >= mPieces.size() || index == mActive) return;
    mActive = index;
    ++mPiecesRevision;
}

std::string Document::freeName(const std::string& base) const
{
    const auto taken = [this](const std::string& name) {
        return std::any_of(mPieces.begin(), mPieces.end(),
                           [&](const DocumentPiece& piece) { return piece.look.name == name; });
    };
    std::string name = base;
    for (int n = 2; taken(name); ++n) name = base + " " + std::to_string(n);
    return name;
}

void Document::beginStroke(const Stroke& settings, StrokeSources sources, bool stopAtOthers)
{
    std::vector<KeepOut> others;
    const openvdb::Mat4d& placement = mPieces[mActive].look.placement;
    for (std::size_t i = 0; i < mPieces.size() && stopAtOthers; ++i)
        if (i != mActive && mPieces[i].look.visible)
            others.push_back({mPieces[i].session->field(), placement * mPieces[i].look.placement.inverse()});
    session().beginStroke(settings, others);
    mPendingSources = std::move(sources);
    mPendingStopAtPieces = stopAtOthers;
}

SculptSession::StrokeReport Document::extendStroke(const StrokeSample& sample)
{
    return session().extendStroke(sample);
}

void Document::endStroke()
{
    SculptSession::FinishedStroke done = session().endStroke();
    ++mRevision;
    if (done.report.leavesChanged == 0) return;  // the history ignores a stroke that changed nothing
    recordStep(strokeLabel(done.stroke, done.report.stamps), {{mPieces[mActive].session}, {}, {}});
    logEvent(script::StrokeEvent{std::move(done.stroke), std::move(mPendingSources), mPendingStopAtPieces}, mActive);
}

void Document::replaceField(FieldImage result, const std::string& label, std::optional<ScriptEvent> scripted)
{
    session().replaceField(std::move(result));
    ++mRevision;
    recordStep(label, {{mPieces[mActive].session}, {}, {}});
    logEdit(std::move(scripted), label, mActive);
}

void Document::logEdit(std::optional<ScriptEvent> scripted, const std::string& label, std::size_t activeBefore)
{
    if (scripted) logEvent(std::move(*scripted), activeBefore);
    else if (mUnscripted.empty()) mUnscripted = label;
}

void Document::logEvent(ScriptEvent event, std::size_t activeBefore)
{
    // A replay sculpts the piece the window sculpted: say so where the two would part.
    if (activeBefore != mLoggedActive) mLog.events.push_back(script::SelectPieceEvent{activeBefore});
    mLog.events.push_back(std::move(event));
    mLoggedActive = mActive;
}

bool Document::editMask(MaskOperation operation, int times)
{
    if (!session().editMask(operation, times)) return false;
    ++mRevision;
    const std::string label = std::string(maskOperationName(operation)) + " mask";
    recordStep(label, {{mPieces[mActive].session}, {}, {}});
    logEvent(script::MaskEvent{operation, times}, mActive);
    return true;
}

void Document::replaceMask(openvdb::FloatGrid::Ptr mask, const std::string& label, ScriptEvent scripted)
{
    session().replaceMask(std::move(mask));
    ++mRevision;
    recordStep(label, {{mPieces[mActive].session}, {}, {}});
    logEvent(std::move(scripted), mActive);
}

void Document::drillHoles(const std::vector<DrainHole>& holes)
{
    session().drillHoles(holes);
    ++mRevision;
    const std::string label = holes.size() == 1 ? "drain hole" : std::to_string(holes.size()) + " drain holes";
    recordStep(label, {{mPieces[mActive].session}, {}, {}});
    for (const DrainHole& hole : holes) logEvent(script::DrainEvent{hole}, mActive);
}

void Document::setLooks(std::vector<PieceLook> looks, const std::string& label)
{
    if (looks.size() != mPieces.size())
        throw InputError("piece looks: " + std::to_string(looks.size()) + " looks for " +
                         std::to_string(mPieces.size()) + " pieces");
    StepScope scope = piecesStep();
    for (std::size_t i = 0; i < looks.size(); ++i) mPieces[i].look = looks[i];
    recordPiecesStep(label, std::move(scope));
    logEvent(script::PieceLooksEvent{std::move(looks), label}, mActive);
}

void Document::movePiece(std::size_t index, const openvdb::Mat4d& placement,
                         std::vector<std::pair<std::size_t, FieldImage>> dented, const std::string& label,
                         std::optional<ScriptEvent> scripted)
{
    StepScope scope = piecesStep();
    script::MovePieceEvent move{index, placement, {}};
    for (auto& [piece, field] : dented) {
        mPieces.at(piece).session->replaceField(std::move(field));
        scope.sessions.push_back(mPieces[piece].session);
        move.pushed.push_back(piece);
    }
    mPieces.at(index).look.placement = placement;
    recordPiecesStep(label, std::move(scope));
    logEvent(scripted ? std::move(*scripted) : ScriptEvent(std::move(move)), mActive);
}

void Document::replacePieces(const std::vector<std::size_t>& replaced, std::vector<DocumentPiece> added,
                             const std::string& label, std::optional<ScriptEvent> scripted)
{
    if (mPieces.size() - replaced.size() + added.size() == 0) throw InputError("a document keeps at least one piece");
    const std::size_t activeBefore = mActive;
    StepScope scope = piecesStep();
    const std::size_t at = replaced.empty() ? mPieces.size() : replaced.front();
    const bool activeGoes = std::find(replaced.begin(), replaced.end(), mActive) != replaced.end();
    std::vector<DocumentPiece> pieces = mPieces;
    for (auto i = replaced.rbegin(); i != replaced.rend(); ++i) pieces.erase(pieces.begin() + std::ptrdiff_t(*i));
    const std::shared_ptr<SculptSession> first = !added.empty() ? added.front().session
                                                 : at > 0       ? mPieces[at - 1].session
                                                                : pieces.front().session;
    pieces.insert(pieces.begin() + std::ptrdiff_t(std::min(at, pieces.size())), std::make_move_iterator(added.begin()),
                  std::make_move_iterator(added.end()));
    restorePieces(pieces, activeGoes || !added.empty() ? first : nullptr);
    recordPiecesStep(label, std::move(scope));
    logEdit(std::move(scripted), label, activeBefore);
}

Document::StepScope Document::piecesStep() const
{
    return {{}, std::make_shared<const std::vector<DocumentPiece>>(mPieces), {}};
}

void Document::recordPiecesStep(const std::string& label, StepScope scope)
{
    scope.after = std::make_shared<const std::vector<DocumentPiece>>(mPieces);
    ++mRevision;
    ++mPiecesRevision;
    recordStep(label, std::move(scope));
}

void Document::recordStep(const std::string& label, StepScope scope)
{
    mUndoLabels.push_back(label);
    countJournalUses(scope, true);
    mUndoScopes.push_back(std::move(scope));
    mRedoLabels.clear();
    mRedoScopes.clear();
    mRedoStates.clear();
    mUndoStates.push_back(mState);
    mState = mNextState++;
    forgetBeyondJournals(mUndoScopes.back().sessions);
}

void Document::countJournalUses(const StepScope& scope, bool add)
{
    for (const auto& session : scope.sessions) {
        std::size_t& uses = mJournalUses[session.get()];
        if (add) ++uses;
        else if (--uses == 0) mJournalUses.erase(session.get());
    }
}

void Document::forgetBeyondJournals(std::vector<std::shared_ptr<SculptSession>> edited)
{
    // Only the sessions just edited can have forgotten a step (a history forgets as it grows).
    const auto forgotten = [&] {
        return std::any_of(edited.begin(), edited.end(), [&](const auto& session) {
            const auto uses = mJournalUses.find(session.get());
            return uses != mJournalUses.end() && uses->second > session->history().undoCount();
        });
    };
    while (!mUndoScopes.empty() && forgotten()) {
        countJournalUses(mUndoScopes.front(), false);
        mUndoLabels.erase(mUndoLabels.begin());
        mUndoScopes.erase(mUndoScopes.begin());
        mUndoStates.erase(mUndoStates.begin());
    }
}

void Document::restorePieces(const std::vector<DocumentPiece>& pieces, std::shared_ptr<SculptSession> active)
{
    if (!active) active = mPieces[mActive].session;
    mPieces = pieces;
    const auto found = std::find_if(mPieces.begin(), mPieces.end(),
                                    [&](const DocumentPiece& piece) { return piece.session == active; });
    mActive = found != mPieces.end() ? std::size_t(found - mPieces.begin()) : std::min(mActive, mPieces.size() - 1);
    ++mPiecesRevision;
}

bool Document::undo()
{
    if (mUndoScopes.empty()) return false;
    const std::size_t activeBefore = mActive;
    const StepScope scope = std::move(mUndoScopes.back());
    mUndoScopes.pop_back();
    countJournalUses(scope, false);
    for (auto session = scope.sessions.rbegin(); session != scope.sessions.rend(); ++session) (*session)->undo();
    if (scope.before) restorePieces(*scope.before);
    else ++mPiecesRevision;  // an edit of a piece not active, perhaps
    mRedoScopes.push_back(scope);
    ++mRevision;
    mRedoLabels.insert(mRedoLabels.begin(), mUndoLabels.back());
    mUndoLabels.pop_back();
    mRedoStates.push_back(mState);
    mState = mUndoStates.back();
    mUndoStates.pop_back();
    logEvent(script::UndoEvent{}, activeBefore);
    return true;
}

bool Document::redo()
{
    if (mRedoScopes.empty()) return false;
    const std::size_t activeBefore = mActive;
    const StepScope scope = std::move(mRedoScopes.back());
    mRedoScopes.pop_back();
    for (const auto& session : scope.sessions) session->redo();
    if (scope.after) restorePieces(*scope.after);
    else ++mPiecesRevision;
    countJournalUses(scope, true);
    mUndoScopes.push_back(scope);
    ++mRevision;
    mUndoLabels.push_back(mRedoLabels.front());
    mRedoLabels.erase(mRedoLabels.begin());
    mUndoStates.push_back(mState);
    mState = mRedoStates.back();
    mRedoStates.pop_back();
    logEvent(script::RedoEvent{}, activeBefore);
    return true;
}

}  // namespace sculpt
