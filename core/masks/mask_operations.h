// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file mask_operations.h
/// @brief What a user does to the whole mask at once: invert, clear, blur, sharpen, grow, shrink.

#include "core/field/dirty_region.h"
#include "core/field/field_image.h"

#include <string>

namespace sculpt {

class LeafJournal;

enum class MaskOperation {
    Invert,   ///< m <- 1 - m over the whole surface (nothing masked becomes all masked)
    Clear,    ///< nothing masked
    Blur,     ///< each value the mean of itself and its six neighbours: a softer edge
    Sharpen,  ///< m <- m^2 (3 - 2 m): values move towards 0 or 1, a crisper edge
    Grow,     ///< each value the largest of itself and its six neighbours: the mask spreads a voxel
    Shrink,   ///< the smallest: the mask recedes a voxel
};

/// "invert", "clear", "blur", "sharpen", "grow", "shrink". @throws InputError for other names.
MaskOperation maskOperationFromName(const std::string& name);
const char* maskOperationName(MaskOperation operation);

/// Applies `operation` `times` times over the whole mask; saves each mask leaf in `journal` (may be
/// null) before it first changes; returns (and marks dirty) the leaves changed. Cost: the band.
/// @throws InputError if times < 1.
DirtyRegion applyMaskOperation(FieldImage& field, MaskOperation operation, int times, LeafJournal* journal);

}  // namespace sculpt
