// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file piece_edits.h
/// @brief What `sculpt pieces` (and the Pieces panel) do to pieces besides moving them: merge
///        two into one, split one into its solids.

#include "core/field/piece.h"

#include <vector>

namespace sculpt {

/// `b` united into a copy of `a` (CSG union), which keeps its name, look and placement; b's
/// voxels are resampled onto a's lattice where their voxel sizes or placements differ.
Piece mergePieces(const Piece& a, const Piece& b);

/// A piece's disjoint solids as pieces of the same look and placement, named "<name> 1",
/// "<name> 2", ... (a cavity stays with the solid around it); a piece of one solid comes back
/// alone, as it was.
std::vector<Piece> splitPiece(const Piece& piece);

}  // namespace sculpt
