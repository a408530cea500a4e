// SPDX-License-Identifier: Apache-2.0
#include "core/motion/morph_verdict.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace sculpt {

double acceptingToleranceVoxels(const MorphSummary& s, double voxelSize)
{
    return std::max(s.finalDistanceWorld, s.worstDistanceWorld - voxelSize) / voxelSize;
}

const char* morphStopName(MorphStop stop)
{
    switch (stop) {
    case MorphStop::Converged: return "converged";
    case MorphStop::Stalled: return "stalled";
    case MorphStop::StepLimit: return "step limit";
    }
    return "";
}

std::string morphVerdict(const MorphSummary& s, double voxelSize)
{
    char tolerance[32];  // rounded up: the tolerance printed must accept the result
    std::snprintf(tolerance, sizeof tolerance, "%.1f", std::ceil(10.0 * acceptingToleranceVoxels(s, voxelSize)) / 10.0);
    switch (s.stop) {
    case MorphStop::Converged: return "converged";
    case MorphStop::Stalled:
        return "NOT converged: the surface stopped approaching the target (40 steps without a 1% gain), so more "
               "steps would not help; its thin parts are finer than the target's voxels resolve: use the target at "
               "a finer voxel size, or a tolerance of " +
               std::string(tolerance) + " voxels accepts this result";
    case MorphStop::StepLimit:
        return "NOT converged: still approaching the target after " + std::to_string(s.steps) +
               " steps: allow more steps";
    }
    return "";
}

}  // namespace sculpt
