// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file mask_selection.h
/// @brief Masking what a rule selects at once: the clay inside a box or lasso drawn on the screen,
///        the cavities (concave creases), the walls thinner than a thickness, one island.
///
/// Each selection gives every voxel a degree s in [0, 1] at its closest surface point; masking
/// raises the mask to at least s (m <- max(m, s)), erasing lowers it to at most 1 - s, so a
/// selection adds to (or takes from) what is masked already, as Blender's box mask does.

#include "core/field/dirty_region.h"
#include "core/field/field_image.h"
#include "core/solids/prism_cut.h"

#include <openvdb/openvdb.h>

#include <string>

namespace sculpt {

class LeafJournal;

enum class MaskSelectionKind {
    Prism,   ///< inside a polygon swept along the view (a box or lasso gesture, prism_cut.h)
    Cavity,  ///< concave creases: fully where the surface curves inwards with a radius of `creaseRadius` or
             ///< less (measured two voxels wide: a wall thinner than four voxels reads its other side too)
    Thin,    ///< walls thinner than `thickness` (wall_thickness.h)
    Island,  ///< the island holding (or nearest) `point` (islands.h)
};

/// "prism", "cavity", "thin", "island". @throws InputError for other names.
MaskSelectionKind maskSelectionFromName(const std::string& name);
const char* maskSelectionName(MaskSelectionKind kind);

struct MaskSelection {
    MaskSelectionKind kind = MaskSelectionKind::Prism;
    bool erase = false;              ///< unmask what is selected instead
    ViewPrism prism{};               ///< Prism
    double creaseRadiusWorld = 1.0;  ///< Cavity: s = -kappa r / 2 (1 for a hollow of radius r)
    double thicknessWorld = 1.0;     ///< Thin
    openvdb::Vec3d point{0.0};       ///< Island
};

/// Masks (or erases) what `selection` selects; saves each mask leaf in `journal` (may be null)
/// before it first changes; returns (and marks dirty) the leaves changed. Cost: the leaves the
/// prism or island reaches, the band for the others (a thickness traces each band voxel's wall).
/// @throws InputError for a prism's polygon of fewer than three points, a radius or thickness
///         not positive and finite, or no island within a band of the point.
DirtyRegion applyMaskSelection(FieldImage& field, const MaskSelection& selection, LeafJournal* journal);

}  // namespace sculpt
