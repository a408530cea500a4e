// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file label_export.h
/// @brief A document's pieces given back to the scan they came from as a segmentation file
///        (`sculpt export-labels`, File > Export Segmentation): the lattice of a reference scan,
///        or of the scan the document keeps, labelled by the pieces (label_map.h) and written as
///        NIfTI, NRRD or a Slicer .seg.nrrd (label_map_files.h).

#include "core/base/progress.h"
#include "core/field/piece.h"
#include "core/scan/label_map.h"

#include <openvdb/openvdb.h>

#include <filesystem>
#include <string>
#include <vector>

namespace sculpt {

/// Where the labels go: the lattice of `like` (any scan readScan reads, or a document keeping
/// one) if given, else of `keptScan`.
/// @throws InputError naming the file when `like` cannot be read, or `document` when it keeps no
///         scan and no `like` is given.
ScanLattice labelLattice(const std::filesystem::path& like, const openvdb::FloatGrid::ConstPtr& keptScan,
                         const std::string& document);

/// Writes the pieces' label map on `lattice` to `output`; returns it (its segments say what went
/// where). @throws InputError naming the file (see writeLabelMap).
LabelMap exportLabels(const std::vector<Piece>& pieces, const ScanLattice& lattice, const std::filesystem::path& output,
                      const Progress& progress = {});

/// "3 labels on 181 x 217 x 181 samples: 1 'liver' (12345 samples), ...": what was written, a line
/// per label; a piece of no sample on the lattice is said to lie off it.
std::vector<std::string> describeLabels(const LabelMap& map);

}  // namespace sculpt
