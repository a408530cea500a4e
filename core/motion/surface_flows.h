// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file surface_flows.h
/// @brief Whole-shape operations built on LevelSetEvolution: smooth and offset.

#include "core/base/progress.h"
#include "core/field/field_image.h"

namespace sculpt {

/// Enough for the flow to reach across a voxel terrace's width several times.
constexpr int kAntiAliasIterations = 40;

/// Mean-curvature smoothing: `iterations` steps of F = -kappa at the largest stable step
/// (dt = h^2 / 6, beta = 1). With keepVolume, a global volume term holds the starting volume.
/// The band is redistanced at the end. Cost: iterations x band.
/// @throws InputError if iterations < 0; Cancelled if progress says stop (field left mid-way,
///         still a valid level set).
void smooth(FieldImage& field, int iterations, bool keepVolume = false, const Progress& progress = {});

/// Whitaker's anti-aliasing of a surface cut from binary data (a mask, a label, a hard-edged
/// scan): mean-curvature flow, as smooth(), but every value of the band is held within half a
/// voxel of where it started, so each voxel centre keeps its side of the binary boundary, and
/// the volume is held too (free of it, the flow settles on the constraints' inner side: a
/// ball's surface 0.18 voxel RMS off the sphere instead of 0.04). The voxel terraces relax into
/// the smoothest surface the samples allow. `iterations` steps at the largest stable step; the
/// band is redistanced at the end. Cost: iterations x band.
/// @throws InputError if iterations < 0; Cancelled if progress says stop.
void antiAlias(FieldImage& field, int iterations = kAntiAliasIterations, const Progress& progress = {});

/// Moves the surface `distanceWorld` along its normal (> 0 grows) by a uniform speed, half a
/// voxel per step, redistancing as it goes. Cost: |distance| / (h / 2) steps x band.
void offset(FieldImage& field, double distanceWorld, const Progress& progress = {});

}  // namespace sculpt
