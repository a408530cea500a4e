#pragma once
/// @file surface_flows.h
/// @brief Whole-shape operations built on LevelSetEvolution: smooth and offset.

#include "core/base/progress.h"
#include "core/field/field_image.h"

namespace sculpt {

/// Mean-curvature smoothing: `iterations` steps of F = -kappa at the largest stable step
/// (dt = h^2 / 6, beta = 1). With keepVolume, a global volume term holds the starting volume.
/// The band is redistanced at the end. Cost: iterations x band.
/// @throws InputError if iterations < 0; Cancelled if progress says stop (field left mid-way,
///         still a valid level set).
void smooth(FieldImage& field, int iterations, bool keepVolume = false, const Progress& progress = {});

/// Moves the surface `distanceWorld` along its normal (> 0 grows) by a uniform speed, half a
/// voxel per step, redistancing as it goes. Cost: |distance| / (h / 2) steps x band.
void offset(FieldImage& field, double distanceWorld, const Progress& progress = {});

}  // namespace sculpt
