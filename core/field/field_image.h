// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file field_image.h
/// @brief The sculpted shape: a narrow-band signed distance field on a sparse grid.
///
/// A FieldImage owns an `openvdb::FloatGrid` of class level set: values are signed distances in
/// world units, negative inside, stored only in a band of `halfWidthVoxels()` voxels on each
/// side of the zero iso-surface; outside the band the grid holds `+-background` (sign only).
/// The voxel size is uniform. Every edit reports the leaves it touched (markDirty), which the
/// mesher and the undo journal consume.

#include "core/base/unique_id.h"
#include "core/field/dirty_region.h"

#include <openvdb/openvdb.h>

#include <string>
#include <utility>

namespace sculpt {

/// The grid every field image starts from: an empty level set named "surface" (the name
/// documents carry) with `background` outside, on a copy of `xform`.
openvdb::FloatGrid::Ptr makeLevelSetGrid(const openvdb::math::Transform& xform, float background);
/// The same on the lattice of voxel size h at the origin, background halfWidthVoxels x h.
openvdb::FloatGrid::Ptr makeLevelSetGrid(double voxelSize, double halfWidthVoxels);

/// An empty mask (a fog grid of background 0 named "mask") on a copy of `xform`.
openvdb::FloatGrid::Ptr makeMaskGrid(const openvdb::math::Transform& xform);

/// Largest |index coordinate| a model may reach: the mesher's edge keys hold 20 bits a
/// coordinate (2^19 either side), less a block's margin.
constexpr int kMaxIndexCoordinate = (1 << 19) - 128;

/// @throws InputError naming `what` if the world box, at voxel size h, reaches farther than
///         kMaxIndexCoordinate voxels from the origin (or is not finite): no model may.
void requireWithinModelExtent(const openvdb::BBoxd& world, double voxelSize, const std::string& what);

class FieldImage {
public:
    /// Narrow-band half width used by the builders: what WENO5 stencils need.
    static constexpr double kDefaultHalfWidthVoxels = 3.0;
    /// Length unit assumed when a file does not say.
    static constexpr const char* kDefaultUnits = "mm";
    /// The frame every document's world is in: LPS (x grows to the patient's left, y to the back,
    /// z up), as DICOM, ITK and Slicer's meshes; the scan readers convert to it (scan_frame.h).
    static constexpr const char* kFrame = "LPS";

    /// Takes ownership of a level-set grid.
    /// @throws InputError if the grid is null, not a level set, has a non-uniform or
    ///         non-linear transform, or a background narrower than one voxel.
    explicit FieldImage(openvdb::FloatGrid::Ptr grid, std::string units = kDefaultUnits);

    /// A field of its own: the grid and the mask copied (a FieldImage copied shares them), the same units.
    FieldImage deepCopy() const;

    /// Edge length of a voxel, in world units.
    double voxelSize() const { return mVoxelSize; }
    /// Half width of the band, in voxels (background / voxel size).
    double halfWidthVoxels() const;
    /// Length unit of world coordinates (e.g. "mm"); metadata only.
    const std::string& units() const { return mUnits; }
    void setUnits(std::string units) { mUnits = std::move(units); }

    const openvdb::FloatGrid& grid() const { return *mGrid; }
    /// Write access for edits; the editor must report what it touched with markDirty().
    openvdb::FloatGrid& mutableGrid() { return *mGrid; }
    openvdb::FloatGrid::ConstPtr gridPtr() const { return mGrid; }
    /// The grid's shared pointer with write access, to hand the whole grid on (an undo record).
    openvdb::FloatGrid::Ptr mutableGridPtr() { return mGrid; }

    /// The mask, or null when nothing is masked: a fog grid (0 free ... 1 held, background 0) on
    /// the field's transform, each voxel painted with its closest surface point's mask and read for
    /// itself (surface_mask.h). Every edit keeps the share of the surface its mask holds.
    const openvdb::FloatGrid* mask() const { return mMask && !mMask->tree().empty() ? mMask.get() : nullptr; }
    /// Write access to the mask, an empty one made on first use; the editor marks what it changed.
    openvdb::FloatGrid& mutableMask();
    /// The mask's shared pointer (null when there is none), to hand it to a copy of the field.
    openvdb::FloatGrid::Ptr maskPtr() const { return mask() ? mMask : nullptr; }
    /// Replaces the mask (null: none). @throws InputError unless it is on the field's transform.
    void setMask(openvdb::FloatGrid::Ptr mask);

    /// Never the same for two field images of this process, a copy's or an assigned one's
    /// included: with a version, what a cache of it (a picker) is keyed on.
    std::uint64_t id() const { return mId.value(); }

    /// Adds leaves to the region touched since the last takeDirtyRegion().
    void markDirty(const DirtyRegion& region) { mDirty.merge(region); }
    const DirtyRegion& dirtyRegion() const { return mDirty; }
    /// Returns the touched region and starts a new, empty one.
    DirtyRegion takeDirtyRegion();
    /// Every leaf of the grid, for edits that change the whole field.
    DirtyRegion allLeaves() const;
    /// Exchanges the grid with `other` (a whole-model edit and its undo); every leaf of both is
    /// marked dirty; the mask stays. @throws InputError unless `other` is a level set on the same transform.
    void swapGrid(openvdb::FloatGrid::Ptr& other);

    /// Whether anything is inside: a voxel or tile of negative distance (an edit that removed
    /// everything leaves only the outside).
    bool enclosesSomething() const;

private:
    UniqueId mId;
    openvdb::FloatGrid::Ptr mGrid;
    openvdb::FloatGrid::Ptr mMask;
    std::string mUnits;
    double mVoxelSize = 0.0;
    DirtyRegion mDirty;
};

}  // namespace sculpt
