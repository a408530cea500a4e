#pragma once
/// @file document.h
/// @brief The open document: the sculpt session (field, live mesh, undo), where it is saved,
///        whether it has unsaved changes, and the log of its edits as a stroke script.

#include "core/io/vdb_file.h"
#include "sculpt/session/sculpt_session.h"
#include "sculpt/session/stroke_script.h"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace sculpt::ui {

/// File > New: a starting shape centred at the origin.
struct NewShape {
    int shape = 0;           ///< 0 sphere, 1 box, 2 torus
    double size = 50.0;      ///< sphere radius, box half side, torus major radius
    double voxelSize = 0.5;  ///< world units
};
inline constexpr const char* kShapeNames[] = {"sphere", "box", "torus"};

class Document {
public:
    /// A document of `field`, saved at `path` (empty: untitled).
    /// `meshing` reports building its mesh (Cancelled if it says stop).
    explicit Document(FieldImage field, std::filesystem::path path = {}, const Progress& meshing = {});

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
    /// @throws InputError naming the file (see writeFieldImage).
    void save();
    void saveAs(const std::filesystem::path& path);
    /// Writes the welded mesh (.ply, .obj, .stl). @throws InputError naming the file.
    void exportMesh(const std::filesystem::path& path) const;
    /// Writes every edit since the document was opened as a `sculpt apply` stroke script.
    /// @throws InputError naming the file if a whole-model edit (a filter) happened: a stroke
    ///         script cannot replay it.
    void saveStrokes(const std::filesystem::path& path) const;

    SculptSession& session() { return mSession; }
    const SculptSession& session() const { return mSession; }
    const std::filesystem::path& path() const { return mPath; }
    /// The opened file's other grids and metadata, written with every save.
    const VdbCompanions& companions() const { return mCompanions; }
    /// The document's pieces besides the one edited (a label map's other labels), shown beside it.
    std::vector<Piece> otherPieces() const { return piecesAmong(mCompanions, mSession.field().units()); }
    /// "face.vdb" or "untitled", with " *" when modified.
    std::string title() const;
    bool modified() const { return mState != mSavedState; }
    /// A recovered document differs from its file until saved.
    void markUnsaved() { mSavedState = ~std::uint64_t(0); }
    /// Changes on every edit, undo and redo: what autosave watches.
    std::uint64_t revision() const { return mRevision; }

    /// Live strokes (see SculptSession); `sources` is what the stroke log writes of its primitive
    /// scene or follow target.
    void beginStroke(const Stroke& settings, StrokeSources sources = {});
    SculptSession::StrokeReport extendStroke(const StrokeSample& sample);
    void endStroke();
    bool undo();
    bool redo();
    /// A whole-model edit's result (SculptSession::replaceField), one undo step named `label`.
    void replaceField(FieldImage result, const std::string& label);

    /// Labels of the strokes that can be undone (oldest first) and redone (next first).
    const std::vector<std::string>& undoLabels() const { return mUndoLabels; }
    const std::vector<std::string>& redoLabels() const { return mRedoLabels; }

private:
    /// A new undo step: its label and the modified-state bookkeeping.
    void recordStep(const std::string& label);

    SculptSession mSession;
    std::filesystem::path mPath;
    VdbCompanions mCompanions;  // the opened file's other grids and metadata
    StrokeScript mLog;
    StrokeSources mPendingSources;
    std::string mUnscripted;  // the first whole-model edit, which the stroke log cannot hold
    std::vector<std::string> mUndoLabels, mRedoLabels;
    std::vector<std::uint64_t> mUndoStates, mRedoStates;
    std::uint64_t mState = 0, mSavedState = 0, mNextState = 1, mRevision = 0;
};

}  // namespace sculpt::ui
