// SPDX-License-Identifier: Apache-2.0
#include "sculpt/session/piece_changes.h"

#include "core/base/errors.h"
#include "core/pieces/lattice_transfer.h"
#include "core/pieces/piece_edits.h"
#include "core/pieces/push.h"
#include "sculpt/session/document.h"

#include <algorithm>

namespace sculpt {

namespace {

/// The piece at `index` as a file holds it; its field shares the session's grid (work deep-copies
/// what it changes).
Piece filed(const Document& document, std::size_t index)
{
    if (index >= document.pieces().size())
        throw InputError("piece " + std::to_string(index) + ": the document has " +
                         std::to_string(document.pieces().size()) + " pieces");
    const DocumentPiece& piece = document.pieces()[index];
    return {piece.look, piece.session->field()};
}

PieceReplacement duplicate(const Document& document, std::size_t index)
{
    Piece copy = filed(document, index);
    const std::string label = "duplicate '" + copy.name + "'";
    copy.name = document.freeName(copy.name + " copy");
    return {label, {}, [copy](const Progress&) { return std::vector<Piece>{Piece(copy, copy.field.deepCopy())}; }};
}

PieceReplacement merge(const Document& document, std::size_t a, std::size_t b)
{
    if (a == b) throw InputError("piece " + std::to_string(a) + " cannot be merged with itself");
    const Piece first = filed(document, std::min(a, b)), second = filed(document, std::max(a, b));
    return {"merge '" + first.name + "' and '" + second.name + "'",
            {std::min(a, b), std::max(a, b)},
            [first, second](const Progress&) { return std::vector<Piece>{mergePieces(first, second)}; }};
}

}  // namespace

PieceReplacement replacementOf(const Document& document, const ScriptEvent& event)
{
    if (const auto* e = std::get_if<script::DuplicatePieceEvent>(&event)) return duplicate(document, e->piece);
    if (const auto* e = std::get_if<script::MergePiecesEvent>(&event)) return merge(document, e->piece, e->with);
    if (const auto* e = std::get_if<script::SplitPieceEvent>(&event)) {
        const Piece piece = filed(document, e->piece);
        return {"split '" + piece.name + "'", {e->piece}, [piece](const Progress&) { return splitPiece(piece); }};
    }
    const auto& removed = std::get<script::DeletePieceEvent>(event);
    const Piece piece = filed(document, removed.piece);
    if (document.pieces().size() < 2)
        throw InputError("a document keeps at least one piece: '" + piece.name + "' is its last");
    return {"delete '" + piece.name + "'", {removed.piece}, [](const Progress&) { return std::vector<Piece>{}; }};
}

PieceMove moveOf(const Document& document, const ScriptEvent& event)
{
    if (const auto* applied = std::get_if<script::ApplyPlacementEvent>(&event)) {
        const Piece piece = filed(document, applied->piece);
        return {"apply the placement of '" + piece.name + "'", applied->piece, openvdb::Mat4d::identity(),
                [piece, index = applied->piece](const Progress&) {
                    // Resampled into its own lattice where it stands now: its placement becomes the identity.
                    PieceFields fields;
                    fields.emplace_back(index, onLatticeOf(piece.field, piece.placement, piece.field,
                                                           openvdb::Mat4d::identity(), piece.field.halfWidthVoxels()));
                    return fields;
                }};
    }
    const auto& move = std::get<script::MovePieceEvent>(event);
    const Piece pusher = filed(document, move.piece);
    std::vector<std::pair<std::size_t, Piece>> others;
    for (std::size_t i : move.pushed) {
        if (i == move.piece) throw InputError("piece " + std::to_string(i) + " cannot push itself");
        others.emplace_back(i, filed(document, i));
    }
    return {"move '" + pusher.name + "'", move.piece, move.placement,
            [pusher, placement = move.placement, others](const Progress& progress) {
                PieceFields dents;
                for (std::size_t k = 0; k < others.size(); ++k) {
                    FieldImage dented = others[k].second.field.deepCopy();
                    pushAside(dented, others[k].second.placement, pusher.field, placement);
                    dents.emplace_back(others[k].first, std::move(dented));
                    report(progress, double(k + 1) / double(others.size()));
                }
                return dents;
            }};
}

}  // namespace sculpt
