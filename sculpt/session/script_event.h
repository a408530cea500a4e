// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file script_event.h
/// @brief One edit of a document as a stroke script records it: a brush stroke, undo and redo, a
///        mask operation or selection, a cut, a drain hole, or an edit of the pieces (which one
///        is sculpted, their looks, a move that may push others aside, a placement applied,
///        duplicate, delete, split, merge). The window logs these as they land; `sculpt apply`
///        and the window's --strokes replay them through applyScriptEvent, bit for bit.

#include "core/field/piece.h"
#include "core/masks/mask_operations.h"
#include "core/masks/mask_selection.h"
#include "core/solids/hollow.h"
#include "core/solids/prism_cut.h"
#include "sculpt/session/stroke.h"

#include <string>
#include <variant>
#include <vector>

namespace sculpt {

/// Where a stroke's extra inputs came from, as a script writes them.
struct StrokeSources {
    std::string primitivesScene;  ///< a primitive stroke's scene as JSON text, written inline
    std::string targetPath;       ///< a follow stroke's target file, as the script names it
};

namespace script {

struct StrokeEvent {
    Stroke stroke;
    StrokeSources sources;
    bool stopAtPieces = false;  ///< the stroke kept out of the other pieces shown
};
struct UndoEvent {};
struct RedoEvent {};
struct MaskEvent {
    MaskOperation operation = MaskOperation::Invert;
    int times = 1;
};
struct MaskSelectionEvent {
    MaskSelection selection;
};
struct CutEvent {
    ViewPrism prism;
    PrismMode mode = PrismMode::Cut;
};
struct DrainEvent {
    DrainHole hole;
};
/// The pieces' edits name pieces by their index in the document, as it is when the event runs.
struct SelectPieceEvent {
    std::size_t piece = 0;  ///< the piece later edits change
};
struct PieceLooksEvent {
    std::vector<PieceLook> looks;  ///< one per piece: names, colours, visibility, placements
    std::string label;             ///< the undo step's name ("rename 'a' to 'b'")
};
struct MovePieceEvent {
    std::size_t piece = 0;
    openvdb::Mat4d placement = openvdb::Mat4d::identity();
    std::vector<std::size_t> pushed;  ///< the pieces it dents aside (keeping their volumes)
};
struct ApplyPlacementEvent {
    std::size_t piece = 0;  ///< resampled where it stands; its placement becomes the identity
};
struct DuplicatePieceEvent {
    std::size_t piece = 0;
};
struct DeletePieceEvent {
    std::size_t piece = 0;
};
struct SplitPieceEvent {
    std::size_t piece = 0;  ///< a piece per closed shell
};
struct MergePiecesEvent {
    std::size_t piece = 0, with = 0;
};

}  // namespace script

using ScriptEvent = std::variant<script::StrokeEvent, script::UndoEvent, script::RedoEvent, script::MaskEvent,
                                 script::MaskSelectionEvent, script::CutEvent, script::DrainEvent,
                                 script::SelectPieceEvent, script::PieceLooksEvent, script::MovePieceEvent,
                                 script::ApplyPlacementEvent, script::DuplicatePieceEvent, script::DeletePieceEvent,
                                 script::SplitPieceEvent, script::MergePiecesEvent>;

}  // namespace sculpt
