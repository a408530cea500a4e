// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file push.h
/// @brief Pieces that do not blend deform on contact (Desbrun, Tsingos and Cani 1995, section 5;
///        Cani, "Implicit representations in computer animation", section 5.1): where one piece
///        is pushed into another, the other gives way like clay.
///
/// The pushed piece is cut by the pusher, max(phi, -phi_pusher), and swells around the dent by
/// what it lost: phi - s w, with w = exp(-(phi_pusher / R)^2) a falloff from the pusher's
/// surface (R = the dent's reach, at least 4 voxels) and s found by the secant method so that the
/// volume (OpenVDB's levelSetVolume) comes back to its value before. The cut is applied last, so
/// no voxel inside the pusher is inside the pushed piece afterwards. Its band is rebuilt.

#include "core/field/dirty_region.h"
#include "core/field/field_image.h"

namespace sculpt {

struct PushReport {
    double volumeBefore = 0.0, volumeAfter = 0.0;  ///< of the pushed piece, world units^3
    double dent = 0.0;                             ///< volume the cut alone removed
    double swell = 0.0;                            ///< s: how far the surface rose at the dent's rim
    int iterations = 0;                            ///< secant steps taken
};

/// Dents `pushed` (placed by `pushedPlacement`; its field edited, every leaf marked dirty) by
/// `pusher` placed by `pusherPlacement`, keeping its volume within `tolerance` (relative).
/// Nothing changes where the two do not overlap.
PushReport pushAside(FieldImage& pushed, const openvdb::Mat4d& pushedPlacement, const FieldImage& pusher,
                     const openvdb::Mat4d& pusherPlacement, double tolerance = 1e-3);

/// A piece kept out of: its field and where it stands relative to the piece being edited (the
/// edited field's world to its own: edited placement * its placement^-1, row vectors).
struct KeepOut {
    FieldImage field;  ///< shares the other piece's grid: read only
    openvdb::Mat4d toOther = openvdb::Mat4d::identity();
};

/// The cut alone, where an edit just changed `field`: in `leaves`, phi = max(phi, -phi_other)
/// (trilinear), so nothing of `field` lies inside `other` there (an add stroke that stops at the
/// other pieces). Leaves whose box misses the other's are not visited.
/// @return the leaves it changed (a subset of `leaves`), marked dirty in `field`.
DirtyRegion keepOut(FieldImage& field, const DirtyRegion& leaves, const KeepOut& other);

}  // namespace sculpt
