#pragma once
/// @file local_patch.h
/// @brief A small copy of the field around an edit, worked on alone and written back in place.
///
/// OpenVDB's tracker and filters visit every leaf of the grid they are given (DESIGN.md), so a
/// local edit copies the leaves near its region into a small grid, edits and renormalises that,
/// then writes back only the voxels inside the region: everything outside stays bit for bit, and
/// the cost follows the region, not the model. The copy reaches a margin beyond the region so
/// that the stencils and the renormalisation read true values wherever they write.

#include "capsule.h"
#include "dirty_region.h"
#include "field_image.h"

namespace sculpt {

class LeafJournal;

/// Origins of the leaves of `grid`'s lattice that may hold a voxel inside `region` (conservative).
std::vector<openvdb::Coord> leavesMeeting(const openvdb::FloatGrid& grid, const Capsule& region);

class LocalPatch {
public:
    /// Voxels beyond the region that renormalise() rebuilds too: the next sub-step's stencils
    /// read them.
    static constexpr double kRenormaliseReachVoxels = 2.0;
    /// Voxels of margin copied beyond the region: what is renormalised plus a WENO5 stencil (3)
    /// and the tracker's dilation, for whole-grid tools run on the copy; one leaf.
    static constexpr double kMarginVoxels = 8.0;

    /// Copies the leaves (and leaf-sized tiles) within `region` grown by the margin.
    LocalPatch(const FieldImage& field, const Capsule& region);

    /// The copy: a field image of its own, for any whole-grid tool (tracker, evolution).
    FieldImage& field() { return mField; }
    const Capsule& region() const { return mRegion; }

    /// Rebuilds the copy's band and |grad phi| = 1 inside the region and a little beyond
    /// (redistanceBand): after each motion of up to a voxel.
    void renormalise();

    /// Writes the copy's voxels inside the region back to `target` (value and active state),
    /// saving each leaf in `journal` before it first changes; marks and returns the changed leaves.
    DirtyRegion commit(FieldImage& target, LeafJournal* journal) const;

private:
    Capsule mRegion;
    std::vector<openvdb::Coord> mInnerLeaves;  // leaves the region meets: the ones commit visits
    FieldImage mField;
};

} // namespace sculpt
