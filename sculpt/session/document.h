// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file document.h
/// @brief The open document: its pieces, each a sculpt session (field, live mesh, undo journal)
///        with its look and placement, the one being edited, where it is saved, whether it has
///        unsaved changes, and the log of its edits as a stroke script.
///
/// One undo history spans the pieces: a step is a journal step of each session it edited (a
/// stroke: the active piece's; a push: the dented pieces') and, when the pieces themselves
/// changed (renamed, moved, added, deleted), the list of pieces before and after it. Pieces share
/// their sessions with the steps that hold them, so a deleted piece comes back whole on undo.

#include "core/io/vdb_file.h"
#include "sculpt/session/piece_meshes.h"
#include "sculpt/session/script_event.h"
#include "sculpt/session/sculpt_session.h"
#include "sculpt/session/stroke_script.h"

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace sculpt {

/// File > New: a starting shape centred at the origin.
struct NewShape {
    enum class Kind { Sphere, Box, Torus };
    Kind kind = Kind::Sphere;
    double size = 50.0;      ///< sphere radius, box half side, torus major radius
    double voxelSize = 0.5;  ///< world units
};
/// The kinds' names, in the order of NewShape::Kind (the New dialog's list).
inline constexpr const char* kShapeNames[] = {"sphere", "box", "torus"};

/// A piece of the open document: its look and its session, shared with the undo steps that
/// hold it.
struct DocumentPiece {
    PieceLook look;
    std::shared_ptr<SculptSession> session;
};

/// A piece's session, meshed live as the window needs it. `meshing` reports its first mesh.
/// Whether a document's pieces keep a live mesh (the window draws them) or none (a replay in batch).
enum class PieceMeshes { Live, None };

DocumentPiece makeDocumentPiece(Piece piece, const Progress& meshing = {}, PieceMeshes meshes = PieceMeshes::Live);

class Document {
public:
    /// A document of one piece, `field`, saved at `path` (empty: untitled).
    /// `meshing` reports building its mesh (Cancelled if it says stop).
    explicit Document(FieldImage field, std::filesystem::path path = {}, const Progress& meshing = {},
                      PieceMeshes meshes = PieceMeshes::Live);
    /// A document of `pieces` (at least one), the first edited.
    explicit Document(std::vector<Piece> pieces, std::filesystem::path path = {}, const Progress& meshing = {},
                      PieceMeshes meshes = PieceMeshes::Live);
    /// Whether its pieces (those added later too) keep live meshes.
    PieceMeshes meshes() const { return mMeshes; }

    /// @throws InputError naming the setting (sizes not positive, too many voxels).
    static Document create(const NewShape& shape);
    /// Reads a document (its other grids and metadata kept for saving); `warnings` gets what
    /// the file could not give whole. @throws InputError naming the file and what is wrong with it.
    /// `grid` names the grid to sculpt in a file of several (empty: readVdbDocument's choice).
    /// `beforeMeshing` sees the field once read, before the mesh is made (a preview of it).
    static Document open(const std::filesystem::path& path, const Progress& progress = {},
                         std::vector<std::string>* warnings = nullptr, const std::string& grid = {},
                         const std::function<void(const FieldImage&)>& beforeMeshing = {});

    /// The document at `documentPath` as its recovery file holds it, unsaved until saved.
    static Document recover(const std::filesystem::path& recoveryFile, std::filesystem::path documentPath);

    /// Writes to path() (atomically), with the other grids and metadata the file held.
    /// @throws InputError naming the file (see writeVdbPieces).
    void save();
    void saveAs(const std::filesystem::path& path);
    /// Writes every piece as save() does, to `path`, leaving the document's own path and state
    /// (a recovery copy).
    void writeCopy(const std::filesystem::path& path) const;
    /// Writes the welded mesh (.ply, .obj, .stl) of every piece shown, where it is placed
    /// (writePieceMeshes: several pieces give a file each, or one OBJ of an object each).
    /// @return what was written, a line per piece. @throws InputError naming the file.
    std::vector<std::string> exportMesh(const std::filesystem::path& path) const;
    /// What exportMesh writes, welded (and checked against `path`'s extension) for a job to write.
    std::vector<PieceMesh> meshesToExport(const std::filesystem::path& path) const;
    /// Writes every edit since the document was opened as a `sculpt apply` stroke script: strokes,
    /// mask and cut edits, drain holes, undo and redo, and the pieces' edits (which is sculpted,
    /// looks, moves and pushes, placements applied, duplicate, delete, split, merge).
    /// @throws InputError naming the file if an edit a stroke script cannot replay happened (a
    ///         filter, an import into the model, primitives baked, a morph frame kept).
    void saveStrokes(const std::filesystem::path& path) const;

    /// The active piece's session: what strokes and whole-model edits change.
    SculptSession& session() { return *mPieces[mActive].session; }
    const SculptSession& session() const { return *mPieces[mActive].session; }
    const std::vector<DocumentPiece>& pieces() const { return mPieces; }
    const std::filesystem::path& path() const { return mPath; }
    std::size_t activePiece() const { return mActive; }
    /// Makes piece `index` the one edited (not an undo step: nothing in the document changes).
    void setActivePiece(std::size_t index);
    /// Changes on every change of the pieces' list or looks and every edit of a piece but the
    /// active one: what the window's drawing of them watches.
    std::uint64_t piecesRevision() const { return mPiecesRevision; }
    /// The pieces with their fields (sharing the sessions' grids), as a file holds them.
    std::vector<Piece> piecesAsFiled() const;
    /// The scan the document was imported from, kept with it (kept_scan.h), or nullptr.
    openvdb::FloatGrid::ConstPtr keptScan() const;
    /// Keeps `scan` (keptScanGrid) with the document in place of any it kept: saved with it.
    void keepScan(openvdb::FloatGrid::Ptr scan);

    /// Piece edits, each one undo step named `label`.
    /// The pieces' new looks, one per piece (renamed, recoloured, hidden, moved: no voxel changes).
    void setLooks(std::vector<PieceLook> looks, const std::string& label);
    /// Piece `index` moved to `placement`, and the pieces `dented` (index, new field) pushed
    /// aside by it, as one step; in the stroke log as `scripted`, else as that move.
    void movePiece(std::size_t index, const openvdb::Mat4d& placement,
                   std::vector<std::pair<std::size_t, FieldImage>> dented, const std::string& label,
                   std::optional<ScriptEvent> scripted = {});
    /// The pieces at `replaced` (ascending) give way to `added`, inserted where the first of them
    /// was (at the end if none): a duplicate, a merge, a split, a delete. The first added becomes
    /// active; else the active piece stays, or if it went, the piece before it. In the stroke log
    /// as `scripted` (none: Save Strokes refuses the log from then on).
    void replacePieces(const std::vector<std::size_t>& replaced, std::vector<DocumentPiece> added,
                       const std::string& label, std::optional<ScriptEvent> scripted = {});
    /// A name for a new piece, not taken yet: `base`, else "base 2", "base 3"...
    std::string freeName(const std::string& base) const;
    /// "face.vdb" or "untitled", with " *" when modified.
    std::string title() const;
    bool modified() const { return mState != mSavedState; }
    /// A recovered document differs from its file until saved.
    void markUnsaved() { mSavedState = ~std::uint64_t(0); }
    /// Changes on every edit, undo and redo: what autosave watches.
    std::uint64_t revision() const { return mRevision; }

    /// Live strokes (see SculptSession); `sources` is what the stroke log writes of its primitive
    /// scene or follow target.
    /// `stopAtOthers`: the stroke keeps out of the other pieces shown (SculptSession::beginStroke).
    void beginStroke(const Stroke& settings, StrokeSources sources = {}, bool stopAtOthers = false);
    SculptSession::StrokeReport extendStroke(const StrokeSample& sample);
    void endStroke();
    bool undo();
    bool redo();
    /// A whole-model edit's result (SculptSession::replaceField), one undo step named `label`;
    /// `scripted`, the event a stroke script replays it by (a cut), else Save Strokes refuses it.
    void replaceField(FieldImage result, const std::string& label, std::optional<ScriptEvent> scripted = {});
    /// A mask operation on the active piece (SculptSession::editMask), one undo step; the stroke
    /// log carries it. False if it changed nothing (no step then).
    bool editMask(MaskOperation operation, int times = 1);
    /// A mask selection's result on the active piece (SculptSession::replaceMask), one undo step
    /// named `label`, in the stroke log as `scripted`.
    void replaceMask(openvdb::FloatGrid::Ptr mask, const std::string& label, ScriptEvent scripted);
    /// Drain holes drilled into the active piece (SculptSession::drillHoles), one undo step.
    void drillHoles(const std::vector<DrainHole>& holes);

    /// Labels of the strokes that can be undone (oldest first) and redone (next first).
    const std::vector<std::string>& undoLabels() const { return mUndoLabels; }
    const std::vector<std::string>& redoLabels() const { return mRedoLabels; }

private:
    /// Puts `scripted` in the stroke log (none: the log cannot replay `label` and is refused).
    void logEdit(std::optional<ScriptEvent> scripted, const std::string& label, std::size_t activeBefore);
    /// Logs `event`, made with piece `activeBefore` sculpted, after selecting that piece in the
    /// log if the log's replay would sculpt another.
    void logEvent(ScriptEvent event, std::size_t activeBefore);
    /// What one undo step changed: one journal step of each of `sessions`, and, if the pieces
    /// changed, their list before and after.
    struct StepScope {
        std::vector<std::shared_ptr<SculptSession>> sessions;
        std::shared_ptr<const std::vector<DocumentPiece>> before, after;
    };
    /// A new undo step: its label, scope and the modified-state bookkeeping.
    void recordStep(const std::string& label, StepScope scope);
    /// A step changing the pieces: begun with their list as it is, recorded with it as it became.
    StepScope piecesStep() const;
    void recordPiecesStep(const std::string& label, StepScope scope);
    /// Drops the oldest steps once a session `edited` has forgotten (its budget) a journal step
    /// they need.
    void forgetBeyondJournals(std::vector<std::shared_ptr<SculptSession>> edited);
    /// Counts (or uncounts) the journal steps `scope` holds in mJournalUses.
    void countJournalUses(const StepScope& scope, bool add);
    /// The pieces become `pieces`; the active piece stays active if it is among them.
    void restorePieces(const std::vector<DocumentPiece>& pieces, std::shared_ptr<SculptSession> active = {});

    std::vector<DocumentPiece> mPieces;
    PieceMeshes mMeshes = PieceMeshes::Live;
    std::size_t mActive = 0;
    std::uint64_t mPiecesRevision = 0;
    std::filesystem::path mPath;
    VdbCompanions mCompanions;  // the opened file's other grids and metadata
    StrokeScript mLog;
    StrokeSources mPendingSources;
    bool mPendingStopAtPieces = false;
    std::size_t mLoggedActive = 0;  // the piece the log's replay sculpts at its end
    std::string mUnscripted;        // the first whole-model edit, which the stroke log cannot hold
    std::vector<std::string> mUndoLabels, mRedoLabels;
    std::vector<StepScope> mUndoScopes, mRedoScopes;
    std::map<const SculptSession*, std::size_t> mJournalUses;  // the undo steps holding a step of each
    std::vector<std::uint64_t> mUndoStates, mRedoStates;
    std::uint64_t mState = 0, mSavedState = 0, mNextState = 1, mRevision = 0;
};

}  // namespace sculpt
