// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file surface_tint.h
/// @brief What colours the clay besides its look: the mask (darker where held) and the print
///        checks (wall thickness and overhang as heat maps), as per-point colours of each chunk
///        uploaded (SurfaceLook darkens or tints its matcaps by them).

#include "core/mesh/block_mesh.h"

#include <openvdb/openvdb.h>

class vtkPolyData;

namespace sculpt::ui {

struct SurfaceTint {
    enum class Check { None, Thickness, Overhang };
    const openvdb::FloatGrid* mask = nullptr;     ///< the field's mask, or null
    const openvdb::FloatGrid* surface = nullptr;  ///< the field, for the thickness
    Check check = Check::None;
    double thinnerThan = 1.0;   ///< thickness: walls thinner than this (world units) glow red
    double steeperThan = 45.0;  ///< overhang: faces closer to facing down than this (degrees) glow blue
    openvdb::Vec3d up{0.0, 0.0, 1.0};

    bool any() const { return mask || check != Check::None; }
    /// The settings that colour every chunk alike (not the grids: their changes come as dirty blocks).
    bool sameSettings(const SurfaceTint& o) const
    {
        return check == o.check && thinnerThan == o.thinnerThan && steeperThan == o.steeperThan && up == o.up;
    }
};

/// "None", "Wall Thickness", "Overhang".
const char* checkName(SurfaceTint::Check check);

/// Colours each point of `poly` (made from `mesh`, in the field's world) by `tint`: the clay,
/// darkened by up to 70% where masked, red where a wall is thinner than the threshold (deeper red
/// the thinner), blue where a face overhangs more steeply than the threshold.
void tintPoints(vtkPolyData& poly, const BlockMesh& mesh, const SurfaceTint& tint);

}  // namespace sculpt::ui
