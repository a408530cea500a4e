// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file morph.h
/// @brief Automatic morphing: the source surface follows a target shape by level-set motion
///        (F_T = -alpha clamp(phi_T, -w, w)), growing where the target is larger and shrinking
///        where it is smaller, through changes of topology, optionally on a straight line of
///        volumes between the two shapes. phi_T is the target's distance widened beyond its band
///        over the whole source (wide_distance.h): far parts travel at the full speed alpha w
///        and the morph sees them approach, so it stops only once the shapes meet or the
///        distance stops falling, whatever their placement. The last
///        frame's approach matches the band's values (TargetTerm::matchValues), so thin parts
///        end on the target too.

#include "core/base/progress.h"
#include "core/field/field_image.h"
#include "core/motion/shape_distance.h"

#include <functional>
#include <vector>

namespace sculpt {

/// Frames one morph may write: frame_0000 ... frame_9999, names that sort as numbers; the disk's
/// room is what bounds it first (a document of the clay ball is about 1 MB).
constexpr int kMaxMorphFrames = 10000;

struct MorphOptions {
    int frames = 10;          ///< frames written, 2 to kMaxMorphFrames: the first is the source
    bool keepVolume = false;  ///< hold V(t) on the line from V_source to V_target
    bool align = false;       ///< translate the source's centroid onto the target's first
    double toleranceVoxels =
        0.4;               ///< converged when each surface is this near the other where the target is resolvable
    int maxSteps = 20000;  ///< give up after this many steps (per pass)
};

/// One frame of the sequence, evenly spaced in morph time.
struct MorphFrame {
    int index;
    double time;
    double volume;
    const FieldImage& field;
};

/// Why the motion ended: what a user can do about a result that is not converged differs.
enum class MorphStop {
    Converged,  ///< within the tolerance
    Stalled,    ///< 40 steps brought no 1% fall of the mean distance: more steps do not help
    StepLimit,  ///< still approaching when maxSteps ran out: more steps would help
};

struct MorphSummary {
    int steps = 0;                  ///< steps of both passes
    double duration = 0.0;          ///< morph time at the last frame
    double finalDistanceWorld = 0;  ///< Hausdorff distance to the target where it is resolvable (shape_distance.h)
    double worstDistanceWorld = 0;  ///< the same over every point, thin parts and sharp edges included
    double resolvedFraction = 1;    ///< share of surface points where the target is resolvable
    bool converged = false;
    MorphStop stop = MorphStop::StepLimit;
    openvdb::Vec3d translation{0.0};  ///< applied by align
    std::vector<double> frameVolumes;
};

/// Morphs `source` into `target`. The source is first resampled into the target's voxels, its mask
/// too: a masked source's frames keep the share of the way from the source its mask holds (held
/// voxels bit for bit the source's; the summary's distances are the free motion's). A first
/// pass finds the time T the morph needs to converge; the second records frames at i T/(N-1),
/// continuing past T if it has not converged yet (the last frame is the final state). Without
/// volume control the second pass starts each frame from the first pass's latest kept state
/// before it. Cost: (time / step) x band steps, plus per frame up to the interval between kept
/// states (twice the steps with keepVolume); a coarse distance field over the source.
/// `onStep`, if given, sees the field after every change of the second pass between two frames
/// (each evolution step, each frame's redistancing): what a mesh tracking the surface follows
/// (core/tracking/mesh_tracker.h). The second pass then steps all the way instead of resuming
/// from the first pass's kept states (a tracked surface cannot follow such a jump): it takes as
/// long as the first.
/// @throws InputError if the shapes do not overlap and align is off, or options are invalid;
///         Cancelled if progress says stop.
MorphSummary morph(const FieldImage& source, const FieldImage& target, const MorphOptions& options,
                   const std::function<void(const MorphFrame&)>& onFrame, const Progress& progress = {},
                   const std::function<void(const FieldImage&)>& onStep = {});

/// Converged: the two-sided distance is within `toleranceWorld` where the target is resolvable,
/// and within a voxel more at its thin parts and sharp edges (so a thin part the surface never
/// reached still counts).
bool morphConverged(const ShapeDistance& distance, double toleranceWorld, double voxelSize);

/// The source as the morph starts from it: in the target's voxels, moved by `shift` (world units)
/// so its centroid sits on the target's if `align`, else not moved.
/// @throws InputError if the shapes do not overlap (then align them).
FieldImage morphStart(const FieldImage& source, const FieldImage& target, bool align, openvdb::Vec3d& shift);

}  // namespace sculpt
