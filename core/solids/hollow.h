// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file hollow.h
/// @brief A solid made a shell of a given thickness, with drain holes: what a resin print needs.
///
/// On a distance field each is a CSG step: the inside shell of thickness t is max(phi, -(phi + t))
/// (the cavity is where phi < -t), the medial one |phi| - t / 2, the outside one max(phi - t, -phi).
/// A closing distance c smooths the cavity's wall: the cavity is eroded by c, then grown by c
/// again, so no part of it is narrower than 2c (the wall thickens into narrow features instead
/// of following them). The band holds distances 3 voxels deep only, so the distances behind the
/// walls come from OpenVDB's levelSetRebuild on a band widened to reach them; the outer wall of
/// an inside shell keeps its voxels bit for bit wherever the cavity is farther than a band.
/// Walls thinner than a voxel are allowed: the field stays continuous and its mesh a closed
/// 2-manifold (a wall thinner than the voxels' spacing may open where no voxel falls inside it).

#include "core/base/progress.h"
#include "core/field/field_image.h"

#include <openvdb/openvdb.h>

#include <optional>
#include <string>
#include <vector>

namespace sculpt {

class LeafJournal;

enum class ShellSide {
    Inside,  ///< the wall within the surface: the outside stays where it was
    Medial,  ///< the wall centred on the surface
    Outside  ///< the wall around the surface: the solid becomes the cavity
};

/// "inside", "medial", "outside". @throws InputError for other names.
ShellSide shellSideFromName(const std::string& name);

struct HollowOptions {
    double thicknessWorld = 2.0;
    ShellSide side = ShellSide::Inside;
    double closingWorld = 0.0;  ///< smooths the cavity's wall (see above); 0: it follows the surface
};

/// A drain hole: a cylinder with round ends (a capsule) from `from` to `to`, cut out of the shell.
struct DrainHole {
    openvdb::Vec3d from{0.0}, to{0.0};
    double radiusWorld = 1.0;
};

struct HollowResult {
    FieldImage field;
    /// The lowest point (along the print direction's "up") of each enclosed cavity, on its wall.
    std::vector<openvdb::Vec3d> cavityBottoms;
};

/// The solid `field` as a shell (see above). Cost: the voxels within the thickness of the surface.
/// @throws InputError if the thickness is not positive and finite, the closing distance negative,
///         or the thickness beyond 1,000 voxels; Cancelled if progress says stop.
HollowResult hollow(const FieldImage& field, const HollowOptions& options, const openvdb::Vec3d& up = {0, 0, 1},
                    const Progress& progress = {});

/// A hole through the bottom wall under each of `bottoms`, straight down along -up, long enough to
/// pass a wall of `wallWorld`: the resin drains from the cavity when the print stands on `up`.
std::vector<DrainHole> drainHolesUnder(const std::vector<openvdb::Vec3d>& bottoms, const openvdb::Vec3d& up,
                                       double wallWorld, double radiusWorld);

/// A hole drilled at `surfacePoint` straight in (along -normal, the outward unit normal there)
/// through the wall to the cavity behind it, reaching a radius beyond both; none if no cavity lies
/// within `farthestWorld` of the surface (a solid part: nothing to drain).
std::optional<DrainHole> drainHoleAt(const FieldImage& field, const openvdb::Vec3d& surfacePoint,
                                     const openvdb::Vec3d& normal, double radiusWorld, double farthestWorld);

/// Cuts the holes out of `field` (CSG difference of each capsule; only the leaves near each hole
/// change), saving each leaf in `journal` (may be null) before it changes.
/// @throws InputError if a radius or an end is not finite, or a radius not positive; nothing
///         changes then.
void cutDrainHoles(FieldImage& field, const std::vector<DrainHole>& holes, LeafJournal* journal = nullptr);

}  // namespace sculpt
