// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file piece_changes.h
/// @brief What an edit of a document's pieces makes, as work on copies of the pieces taken when
///        it is asked for: the window runs the work as a job and lands its result on the UI
///        thread, a replay runs it at once; both land it with the same Document call, so their
///        grids agree bit for bit.

#include "core/base/progress.h"
#include "core/field/piece.h"
#include "sculpt/session/script_event.h"

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace sculpt {

class Document;

/// Fields made anew for pieces, by index (dented aside, a placement resampled).
using PieceFields = std::vector<std::pair<std::size_t, FieldImage>>;

/// A duplicate, split, merge or delete: the pieces at `replaced` (ascending) give way to those
/// `work` makes.
struct PieceReplacement {
    std::string label;
    std::vector<std::size_t> replaced;
    std::function<std::vector<Piece>(const Progress&)> work;
};

/// A move (pushing pieces aside) or a placement applied: piece `piece` placed at `placement`, and
/// the fields `work` makes.
struct PieceMove {
    std::string label;
    std::size_t piece = 0;
    openvdb::Mat4d placement = openvdb::Mat4d::identity();
    std::function<PieceFields(const Progress&)> work;
};

/// The replacement `event` asks of `document` (DuplicatePiece, SplitPiece, MergePieces,
/// DeletePiece). @throws InputError naming a piece index the document does not have.
PieceReplacement replacementOf(const Document& document, const ScriptEvent& event);
/// The move `event` asks (MovePiece, ApplyPlacement). @throws InputError as replacementOf.
PieceMove moveOf(const Document& document, const ScriptEvent& event);

}  // namespace sculpt
