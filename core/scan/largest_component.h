// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file largest_component.h
/// @brief Keeps the largest solid piece of a shape, without cavities: one closed shell to print.
///
/// Scans are full of islands (specks of bright noise) and bubbles (dark pockets inside tissue).
/// The solid is the inside plus every pocket of outside that the exterior cannot reach; its
/// face-connected pieces are the components, and the largest by volume is kept: islands become
/// outside, pockets inside. Works in place on the field: the only copies are bit masks.

#include "core/base/progress.h"
#include "core/field/field_image.h"

#include <cstddef>

namespace sculpt {

struct LargestComponentReport {
    std::size_t islandsDropped = 0;  ///< solid pieces other than the largest
    std::size_t cavitiesFilled = 0;  ///< pockets of outside the exterior cannot reach
};

/// Keeps the solid piece with the most voxels, its cavities filled.
LargestComponentReport keepLargestComponent(FieldImage& field, const Progress& progress = {});

}  // namespace sculpt
