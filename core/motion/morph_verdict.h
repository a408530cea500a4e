// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file morph_verdict.h
/// @brief What a morph's result means for its user: which rule stopped it and what would help.

#include "core/motion/morph.h"

#include <string>

namespace sculpt {

/// The tolerance (in the target's voxels) at which `summary` would count as converged.
double acceptingToleranceVoxels(const MorphSummary& summary, double voxelSize);

/// "converged", "stalled" or "step limit": the stop rule's name in reports.
const char* morphStopName(MorphStop stop);

/// One sentence for the user: converged, or which rule stopped the motion and what would help
/// (more steps only when they would; else a finer target, or the tolerance that accepts it).
std::string morphVerdict(const MorphSummary& summary, double voxelSize);

}  // namespace sculpt
