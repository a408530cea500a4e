// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file sculpt_session.h
/// @brief The document being sculpted: its field, its undo history and, optionally, a live mesh.
///
/// Everything the UI and the scripts do to a document goes through here: a stroke is applied
/// stamp by stamp (each stamp journals the leaves it changes; the mesher later re-meshes just
/// those), then recorded as one undo step.

#include "core/field/field_image.h"
#include "core/masks/mask_operations.h"
#include "core/masks/mask_selection.h"
#include "core/mesh/incremental_mesher.h"
#include "core/pieces/push.h"
#include "core/solids/hollow.h"
#include "sculpt/session/stroke.h"
#include "sculpt/session/undo_history.h"

#include <memory>
#include <optional>

namespace sculpt {

class SculptSession {
public:
    /// @param liveMesh keep an IncrementalMesher up to date (the UI does; see updateMesh()).
    /// @param meshing reports the first full mesh (Cancelled if it says stop).
    explicit SculptSession(FieldImage field, bool liveMesh = false,
                           std::size_t undoBudgetBytes = UndoHistory::kDefaultBudgetBytes,
                           const Progress& meshing = {});
    ~SculptSession();
    SculptSession(SculptSession&&) noexcept;
    SculptSession& operator=(SculptSession&&) noexcept;

    /// What a stroke did.
    struct StrokeReport {
        std::size_t stamps = 0;
        std::size_t leavesChanged = 0;
        std::size_t journalBytes = 0;
    };
    /// Applies the stroke and records it as one undo step.
    /// @throws InputError (brush settings, samples) before changing anything.
    StrokeReport applyStroke(const Stroke& stroke);

    /// A stroke drawn live: begin, then each sample stamps what is due at once, then end records
    /// it as one undo step. The samples kept are the stroke's, so `sculpt apply` replays it bit
    /// for bit. @throws InputError (settings, a brush larger than the model) before any change.
    /// With `keepOutOf`, every stamp is cut by those pieces where it reaches into them (keepOut:
    /// an add stroke that stops at the other pieces).
    void beginStroke(const Stroke& settings, std::vector<KeepOut> keepOutOf = {});
    /// @throws InputError if a sample is not finite or its pressure not in (0, 1]; nothing changes.
    StrokeReport extendStroke(const StrokeSample& sample);
    struct FinishedStroke {
        Stroke stroke;  ///< with every sample
        StrokeReport report;
    };
    /// Stamps the closing stamp and records the stroke as one undo step.
    FinishedStroke endStroke();
    /// Puts the field back as before the live stroke and forgets it.
    void cancelStroke();
    bool strokeActive() const { return mLive != nullptr; }
    /// The live stroke's journal (what its stamps changed, as it was before), or null.
    const LeafJournal* strokeJournal() const;
    /// Makes `result` (a whole-model edit of this field: a filter, a morph frame) the field, as
    /// one undo step that keeps the whole previous grid. Not during a live stroke.
    /// @throws InputError unless `result` has the field's transform; nothing changes then.
    void replaceField(FieldImage result);
    /// Applies a mask operation (invert, clear, blur, ...) `times` times to the whole mask, as one
    /// undo step; false if it changed nothing (no step then). Not during a live stroke.
    /// @throws InputError if times < 1; nothing changes then.
    bool editMask(MaskOperation operation, int times = 1);
    /// Masks (or erases) what `selection` selects (a box or lasso, the cavities, the thin walls, an
    /// island), as one undo step; false if it changed nothing. Not during a live stroke.
    /// @throws InputError as applyMaskSelection; nothing changes then.
    bool selectMask(const MaskSelection& selection);
    /// Makes `mask` (null: none) the field's mask whole, as one undo step: a mask selection made
    /// on a copy of the field (off the UI thread) landing. Not during a live stroke.
    /// @throws InputError unless it is on the field's transform; nothing changes then.
    void replaceMask(openvdb::FloatGrid::Ptr mask);
    /// Cuts drain holes (a hollow model's, hollow.h) as one undo step. Not during a live stroke.
    /// @throws InputError as cutDrainHoles; nothing changes then.
    void drillHoles(const std::vector<DrainHole>& holes);
    bool undo();
    bool redo();

    const FieldImage& field() const { return mField; }
    /// Gives the field away (the session is spent).
    FieldImage takeField() { return std::move(mField); }
    const UndoHistory& history() const { return mHistory; }
    /// The live mesh, if the session keeps one.
    const IncrementalMesher* mesher() const { return mMesher ? &*mMesher : nullptr; }

    /// Blocks the live mesh re-meshed since the session began (the mesher's own count).
    std::size_t remeshedBlocks() const { return mRemeshed; }

    /// Largest extent of the model's band, world units: brushes larger than this are refused.
    /// A pass over the tree's nodes: not per event.
    double modelSize() const;

    /// Re-meshes the blocks changed since the last call. A live stroke's stamps do not (the UI
    /// calls this once per frame, so events never wait for the mesher); every other edit, and
    /// a stroke's end, re-mesh at once.
    void updateMesh();

private:
    struct LiveStroke;
    openvdb::CoordBBox leafBox() const;
    double sizeOf(const openvdb::CoordBBox& leafBox) const;
    void checkRadius(const BrushSettings& brush, double modelSize) const;
    /// @throws InputError if the sample lies far beyond the model (its stamps would reach nothing).
    void checkNearModel(const StrokeSample& sample, std::size_t index) const;
    void stamp(const std::vector<BrushStamp>& stamps, StrokeReport& report);

    FieldImage mField;
    UndoHistory mHistory;
    std::optional<IncrementalMesher> mMesher;
    std::unique_ptr<LiveStroke> mLive;
    std::size_t mRemeshed = 0;
};

/// Samples one stroke may hold: a 40 Hz pointer for 40 minutes.
constexpr std::size_t kMaxStrokeSamples = 100000;
/// Stamps one stroke may make, mirrors included: about two minutes of stamping.
constexpr std::size_t kMaxStrokeStamps = 100000;

/// @throws InputError naming the field if a sample is not finite or its pressure not in (0, 1],
///         there are no samples or more than kMaxStrokeSamples, the stroke needs more than
///         kMaxStrokeStamps stamps, the spacing is not in [0.01, 4], or the brush settings are invalid.
void validateStroke(const Stroke& stroke);
/// @throws InputError if a stroke of `samples` samples is more than one may hold (checked
///         before they are parsed).
void requireSampleCount(std::size_t samples);

}  // namespace sculpt
