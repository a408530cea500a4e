// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file label_map.h
/// @brief A document's pieces given back as a segmentation: a label per sample of a scan's
///        lattice, the piece whose surface holds the sample's centre.
///
/// A sample inside several pieces (pieces may overlap where they were never pushed apart) goes
/// to the one it is deepest in. Each piece keeps the label it was imported with (PieceLook::label);
/// the others, and a second piece claiming a label taken, get the smallest unused values. The
/// cost follows the pieces: only the samples inside a piece's box are visited.

#include "core/base/progress.h"
#include "core/field/piece.h"
#include "core/scan/scan_lattice.h"

#include <cstdint>
#include <string>
#include <vector>

namespace sculpt {

/// One label of a label map: the piece it came from.
struct LabelSegment {
    int label = 0;
    std::string name;
    openvdb::Vec3f colour{0.8f, 0.8f, 0.8f};  ///< sRGB 0..1
    openvdb::CoordBBox extent;                ///< the index box of its samples; empty if none
    std::size_t samples = 0;
};

struct LabelMap {
    ScanLattice lattice;
    std::vector<std::uint16_t> labels;  ///< one per sample, i fastest, then j, then k; 0: background
    std::vector<LabelSegment> segments;
    int largestLabel() const;
};

/// The pieces on `lattice`. @throws InputError if the lattice would not fit in memory;
/// Cancelled if `progress` says stop.
LabelMap labelMapOf(const std::vector<Piece>& pieces, const ScanLattice& lattice, const Progress& progress = {});

}  // namespace sculpt
