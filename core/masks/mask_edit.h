// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file mask_edit.h
/// @brief The one way the mask is written: a rule gives each voxel of some of the field's leaves
///        its new mask value, journalled with the surface.
///
/// The mask is kept on the field's leaves (the band and the voxels sharing its leaves), each voxel
/// read for itself (surface_mask.h); rules give a voxel the mask of its closest surface point
/// (MaskSite::footWorld), so the band under a patch of surface is held alike. Values are clamped to [0, 1]; 0 is
/// stored inactive. Rules read the mask as it was (every value is found before any is written),
/// so the order of voxels does not matter, and the field's leaves are marked dirty so the display
/// re-tints them.

#include "core/field/dirty_region.h"
#include "core/field/field_image.h"

#include <openvdb/openvdb.h>

#include <functional>
#include <optional>
#include <vector>

namespace sculpt {

class LeafJournal;

/// What a rule may read at a voxel; one per thread.
class MaskSite {
public:
    explicit MaskSite(const FieldImage& field);
    /// The mask stored at a voxel (0 where none).
    double mask(const openvdb::Coord& ijk) const { return mMask ? double(mMask->getValue(ijk)) : 0.0; }
    /// The voxel's closest surface point, in world units (the voxel itself outside the band).
    openvdb::Vec3d footWorld(const openvdb::Coord& ijk) const;
    const openvdb::FloatGrid::ConstAccessor& surface() const { return mSurface; }

private:
    const openvdb::math::Transform& mTransform;
    openvdb::FloatGrid::ConstAccessor mSurface;
    std::optional<openvdb::FloatGrid::ConstAccessor> mMask;
};

/// The new mask at voxel ijk (clamped to [0, 1] afterwards); called from several threads.
using MaskRule = std::function<double(const openvdb::Coord& ijk, const MaskSite& site)>;

/// Every leaf origin of the field's grid: the whole mask's domain.
std::vector<openvdb::Coord> maskDomain(const FieldImage& field);

/// Sets the mask at every voxel of the given leaves (those the field has) to rule(ijk); saves each
/// mask leaf in `journal` (may be null) before it first changes. Returns the leaves changed, also
/// marked dirty in the field.
DirtyRegion rewriteMask(FieldImage& field, const std::vector<openvdb::Coord>& leafOrigins, LeafJournal* journal,
                        const MaskRule& rule);

}  // namespace sculpt
