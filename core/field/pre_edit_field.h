// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file pre_edit_field.h
/// @brief A read-only view of a field as it was before the edits a LeafJournal holds, without
///        copying it: a voxel of a leaf the journal saved reads the saved state, every other
///        voxel the field itself.
///
/// A stroke's picks need the surface as it was when the stroke began (see SurfacePicker); the
/// stroke's own journal already keeps that surface's changed leaves, so a copy of the whole grid
/// per stroke (189 MB for an 8 M-triangle scan) is not needed. Reading costs one map look-up per
/// leaf entered (the last one is remembered), so a view is for one thread and one query.

#include "core/field/field_image.h"
#include "core/field/leaf_journal.h"

#include <optional>

namespace sculpt {

class PreEditField {
public:
    /// `edits`: the journal of the edits made to `field` since the state to be read (null: none).
    /// Both must outlive the view and not change while it is read.
    PreEditField(const FieldImage& field, const LeafJournal* edits);

    const FieldImage& field() const { return mField; }
    /// Phi at voxel ijk, world units.
    float value(const openvdb::Coord& ijk) const;
    /// Phi at an index-space point, trilinear between its eight voxels.
    double sample(const openvdb::Vec3d& index) const;
    /// The gradient of sample() at an index-space point, per voxel (central differences half a
    /// voxel either side).
    openvdb::Vec3d gradient(const openvdb::Vec3d& index) const;

private:
    const FieldImage& mField;
    const LeafJournal* mEdits;
    openvdb::FloatGrid::ConstAccessor mAccessor;
    mutable openvdb::Coord mLeafOrigin{openvdb::Int32(0x7fffffff)};  // of the last journal look-up
    mutable std::optional<LeafJournal::SavedState> mSaved;
};

}  // namespace sculpt
