#pragma once
/// @file morph.h
/// @brief Automatic morphing: the source surface follows a target shape by level-set motion
///        (F_T = -alpha clamp(phi_T, -w, w)), growing where the target is larger and shrinking
///        where it is smaller, through changes of topology, optionally on a straight line of
///        volumes between the two shapes.

#include "core/base/progress.h"
#include "core/field/field_image.h"

#include <functional>
#include <vector>

namespace sculpt {

struct MorphOptions {
    int frames = 10;               ///< frames written, >= 2: the first is the source
    bool keepVolume = false;       ///< hold V(t) on the line from V_source to V_target
    bool align = false;            ///< translate the source's centroid onto the target's first
    double toleranceVoxels = 0.4;  ///< converged when every surface point is this near the target
    int maxSteps = 20000;          ///< give up after this many steps (per pass)
};

/// One frame of the sequence, evenly spaced in morph time.
struct MorphFrame {
    int index;
    double time;
    double volume;
    const FieldImage& field;
};

struct MorphSummary {
    int steps = 0;                  ///< steps of the recorded pass
    double duration = 0.0;          ///< morph time at the last frame
    double finalDistanceWorld = 0;  ///< surfaceDistance() of the final surface
    bool converged = false;
    openvdb::Vec3d translation{0.0};  ///< applied by align
    std::vector<double> frameVolumes;
};

/// Morphs `source` into `target`. The source is first resampled into the target's voxels. A first
/// pass finds the time T the morph needs to converge; the second records frames at i T/(N-1),
/// continuing past T if it has not converged yet (the last frame is the final state).
/// Cost: two passes of (time / step) x band steps.
/// @throws InputError if the shapes do not overlap and align is off, or options are invalid;
///         Cancelled if progress says stop.
MorphSummary morph(const FieldImage& source, const FieldImage& target, const MorphOptions& options,
                   const std::function<void(const MorphFrame&)>& onFrame, const Progress& progress = {});

/// How far the surface of `field` is from the target's: max |phi_T| (trilinear) over the points
/// where the surface crosses grid edges. Both grids must share their transform.
double surfaceDistance(const FieldImage& field, const FieldImage& target);

}  // namespace sculpt
