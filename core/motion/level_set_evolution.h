// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file level_set_evolution.h
/// @brief Moves a field image's surface under a composite normal speed (motion_terms.h).
///
/// Numerics: dphi/dt = -F_adv |grad phi| + beta kappa |grad phi|, where F_adv gathers the target,
/// volume and offset terms. The advective part uses Godunov's upwind |grad phi| built from HJ-WENO5
/// one-sided differences (or first-order ones); the curvature part central differences; time
/// integration is the TVD Runge-Kutta of order 2 (Heun). Steps obey the CFL limits
/// dt <= cfl h / max|F_adv| and dt <= h^2 / (6 beta), where the target term's share of max|F_adv|
/// is clamped to what the previous step read near the surface plus a voxel. Each leaf is processed on a dense copy
/// with a 3-voxel apron (gatherDense), in parallel. Once any level set of the band may have moved
/// half a voxel (max|F_adv| t), or curvature diffusion may have carried the band edge's error half
/// a voxel (beta t >= h^2 / 2), the band is rebuilt and redistanced with
/// openvdb::tools::LevelSetTracker.
///
/// A masked field (FieldImage::mask) keeps, after every step, the share of it the mask holds at
/// each voxel's closest surface point: the speed times (1 - mask); held voxels stay bit for bit.
///
/// A step visits every leaf (OpenVDB's tracker does too): a local motion runs on a LocalPatch's
/// copy of the leaves around it, as the smoothing brush does.

#include "core/field/field_image.h"
#include "core/motion/motion_terms.h"

#include <functional>

namespace sculpt {

enum class GradientScheme { FirstOrder, Weno5 };

struct EvolutionOptions {
    GradientScheme scheme = GradientScheme::Weno5;  ///< upwind differences of the advection
    double cfl = 0.5;                               ///< fraction of a voxel the surface may move per step
    double redistanceAfterMovingVoxels = 0.5;       ///< rebuild the band once the surface may have moved this far
    double redistanceAfterDiffusingVoxels2 = 0.5;   ///< ... or once beta t (curvature diffusion) reaches this h^2
    int normalizeIterations = 1;                    ///< LevelSetTracker normalisation sweeps per rebuild
    /// Forward Euler instead of TVD-RK2: half the work, for motions whose path in time does not
    /// matter, only where they lead (a smoothing brush); same stability limit for diffusion.
    bool firstOrderTime = false;
};

class LevelSetEvolution {
public:
    /// @throws InputError for non-finite or negative coefficients, or a target whose voxel size
    ///         differs from the field's.
    LevelSetEvolution(FieldImage& field, MotionTerms terms, EvolutionOptions options = {});

    /// Largest stable step for the current terms.
    double stableTimeStep() const;
    /// One TVD-RK2 step of min(maxDt, stableTimeStep()); returns the step taken.
    double step(double maxDt = std::numeric_limits<double>::infinity());
    /// Steps until `duration` has elapsed (the last step is shortened to land on it).
    void advance(double duration);
    /// Rebuilds and redistances the band now (done automatically as the surface moves).
    void redistance();
    /// With volume control: offsets the surface until its mesh volume is the target's within
    /// 0.01% (a few Newton steps, each one meshing): before a result is written.
    void settleVolume();

    double time() const { return mTime; }
    int stepCount() const { return mSteps; }
    MotionTerms& terms() { return mTerms; }

private:
    struct Work;
    /// Runs an edit of the whole field, then holds the share of it the field's mask holds.
    template <typename Edit>
    void heldByMask(const Edit& edit);
    void applyStep(double dt);
    /// Volume control by operator splitting: after the other terms' step, a uniform offset
    /// brings the volume back to its target.
    void correctVolume();
    /// Mesh volume minus the band estimate, measured now.
    void calibrateVolume();
    /// Moves the surface by `displacement` along its normal (> 0 grows): every active value
    /// lowered by it, within the band.
    void offsetValues(double displacement);
    double maxAdvectionSpeed() const;
    /// Bounds the target term's next speed by what the last step read.
    void updateTargetReach(double fastest);

    FieldImage& mField;
    MotionTerms mTerms;
    EvolutionOptions mOptions;
    double mTime = 0.0;
    int mSteps = 0;
    double mMovedSinceRedistance = 0.0;
    double mVolumeBias = 0.0;  // mesh volume - band estimate, at the last calibration
    int mCalibratedAt = -1;    // step of the last calibration
    double mDiffusedSinceRedistance = 0.0;
    // The target term's clamp for the next step, world units: the clamp w, or less once the
    // surface is nearer the target than w. Near convergence it falls well below w, so steps
    // grow (the CFL limit follows the speed the surface actually has).
    double mTargetReach = 0.0;
};

}  // namespace sculpt
