// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file motion_terms.h
/// @brief The terms of the normal speed that moves a level set (Cani, eq. 1):
///        F = F_target + F_smooth + F_volume + F_offset, with dphi/dt + F |grad phi| = 0 and
///        F > 0 moving the surface outwards.

#include "core/local/falloff.h"

#include <openvdb/openvdb.h>

#include <optional>

namespace sculpt {

/// F_T = -alpha clamp(phi_T(x), -w, w): the surface moves towards the target's zero set, at
/// most alpha w fast. The target must share the field's transform (resample first).
struct TargetTerm {
    openvdb::FloatGrid::ConstPtr target;
    double alpha = 1.0;       ///< per unit time
    double clampWorld = 0.0;  ///< w; 0 means the target's band half width
    /// F_T = -alpha clamp(phi_T(x) - phi(x), -w, w) at each voxel instead (OpenVDB's
    /// LevelSetMorphing): the same speed on the surface, but every value of the band converges
    /// on the target's, so parts thinner than the band, which only its values hold, do too.
    bool matchValues = false;
};

/// F_k = -beta kappa, kappa = div(grad phi / |grad phi|) (2/r on a sphere): mean-curvature flow.
/// A sphere follows r(t)^2 = r0^2 - 4 beta t.
struct SmoothTerm {
    double beta = 1.0;  ///< world units^2 per unit time
    /// If set, beta is scaled by this ball's falloff at each voxel: a smoothing brush.
    std::optional<FalloffBall> weight;
};

/// F_V = gamma (V* - V) / (A tau), V and A measured on the current surface, tau the step: a
/// uniform normal speed that restores the volume V* (global, never local). Applied by operator
/// splitting: after the other terms' step, the surface is offset by gamma (V* - V) / A, so the
/// volume the other terms lost or gained in the step is restored in the same step, without lag.
/// V is the volume of the marching-cubes mesh (what `info`, the export and a printer see): each
/// step reads the fast band estimate, corrected by its difference from the mesh's volume, which
/// is measured every few steps (the two differ at sharp edges, by an amount that changes slowly).
struct VolumeTerm {
    double targetVolume = 0.0;  ///< V* at the end of the next step, world units^3, of the mesh
    double gamma = 1.0;         ///< fraction of the volume error corrected per step
};

/// F = speed everywhere: the surface offsets along its normal.
struct UniformTerm {
    double speedWorld = 0.0;  ///< world units per unit time; > 0 grows
};

struct MotionTerms {
    std::optional<TargetTerm> target;
    std::optional<SmoothTerm> smooth;
    std::optional<VolumeTerm> volume;
    std::optional<UniformTerm> uniform;
};

}  // namespace sculpt
