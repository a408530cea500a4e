#pragma once
/// @file sculpt_session.h
/// @brief The document being sculpted: its field, its undo history and, optionally, a live mesh.
///
/// Everything the UI and the scripts do to a document goes through here: a stroke is applied
/// stamp by stamp (each stamp journals the leaves it changes, then the mesher re-meshes just
/// those), then recorded as one undo step.

#include "core/field/field_image.h"
#include "core/mesh/incremental_mesher.h"
#include "sculpt/session/stroke.h"
#include "sculpt/session/undo_history.h"

#include <optional>

namespace sculpt {

class SculptSession {
public:
    /// @param liveMesh keep an IncrementalMesher up to date after every stamp (the UI does).
    explicit SculptSession(FieldImage field, bool liveMesh = false,
                           std::size_t undoBudgetBytes = UndoHistory::kDefaultBudgetBytes);

    /// What a stroke did.
    struct StrokeReport {
        std::size_t stamps = 0;
        std::size_t leavesChanged = 0;
        std::size_t journalBytes = 0;
    };
    /// Applies the stroke and records it as one undo step.
    /// @throws InputError (brush settings, samples) before changing anything.
    StrokeReport applyStroke(const Stroke& stroke);
    bool undo();
    bool redo();

    const FieldImage& field() const { return mField; }
    /// Gives the field away (the session is spent).
    FieldImage takeField() { return std::move(mField); }
    const UndoHistory& history() const { return mHistory; }
    /// The live mesh, if the session keeps one.
    const IncrementalMesher* mesher() const { return mMesher ? &*mMesher : nullptr; }

    /// Largest extent of the model's band, world units: brushes larger than this are refused.
    double modelSize() const;

private:
    void updateMesh();

    FieldImage mField;
    UndoHistory mHistory;
    std::optional<IncrementalMesher> mMesher;
};

/// @throws InputError naming the field if a sample is not finite or its pressure not in (0, 1],
///         there are no samples, the spacing is not in (0, 4], or the brush settings are invalid.
void validateStroke(const Stroke& stroke);

}  // namespace sculpt
