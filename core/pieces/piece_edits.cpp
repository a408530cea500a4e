// SPDX-License-Identifier: Apache-2.0
#include "core/pieces/piece_edits.h"

#include "core/field/csg_combine.h"
#include "core/pieces/lattice_transfer.h"

#include <openvdb/tools/LevelSetUtil.h>

namespace sculpt {

Piece mergePieces(const Piece& a, const Piece& b)
{
    Piece merged = a;
    merged.field = a.field.deepCopy();
    combine(merged.field, onLatticeOf(b.field, b.placement, a.field, a.placement, a.field.halfWidthVoxels()),
            CsgOperation::Union);
    return merged;
}

std::vector<Piece> splitPiece(const Piece& piece)
{
    std::vector<openvdb::FloatGrid::Ptr> solids;
    openvdb::tools::segmentSDF(piece.field.grid(), solids);
    if (solids.size() < 2) return {piece};
    std::vector<Piece> parts;
    for (std::size_t i = 0; i < solids.size(); ++i) {
        Piece part = piece;
        solids[i]->setName("");
        part.field = FieldImage(solids[i], piece.field.units());
        part.name = piece.name + " " + std::to_string(i + 1);
        parts.push_back(std::move(part));
    }
    return parts;
}

}  // namespace sculpt
