#pragma once
/// @file surface_mask.h
/// @brief Reading the field's mask where an edit lands, and holding the share of the edit it holds.
///
/// The mask (FieldImage::mask) lives on the field's voxels but belongs to the surface: a voxel's
/// weight m is the mask at the voxel's closest surface point (trilinear), as the follow brush
/// reads its target, so the whole band under a masked patch of surface is held alike. An edit
/// that would take a voxel from v to v' leaves it at v + (1 - m)(v' - v): every speed times
/// (1 - m). Where m = 1 the voxel keeps v bit for bit; where m = 0 it takes v' bit for bit.

#include "core/field/band_rule.h"
#include "core/field/field_image.h"

#include <openvdb/openvdb.h>

namespace sculpt {

/// Reads a mask at the closest points of a surface (the field before an edit). Holds accessors:
/// one reader per thread.
class MaskReader {
public:
    MaskReader(const openvdb::FloatGrid& surface, const openvdb::FloatGrid& mask);
    /// The mask, clamped to [0, 1], at voxel ijk's closest surface point (outside the band, where
    /// the field knows only its sign, at the voxel itself).
    double at(const openvdb::Coord& ijk) const;
    /// The same at any lattice point of the surface's index space.
    double atIndex(const openvdb::Vec3d& index, float phi, const openvdb::Vec3d& difference) const;

private:
    openvdb::FloatGrid::ConstAccessor mSurface, mMask;
    double mInvVoxel;
};

/// What the band stores of a voxel the edit took from `before` to `after` once the mask `m` held
/// its share: `before` exactly for m >= 1, `after` exactly for m <= 0.
inline BandValue maskedValue(float before, float after, double m, float background)
{
    if (m >= 1.0) return toBand(before, background);
    if (m <= 0.0) return toBand(after, background);
    return toBand(float(double(before) + (1.0 - m) * (double(after) - double(before))), background);
}

/// Holds the share of an edit of the whole field that the field's mask holds, at every voxel
/// where `field` and `before` (the field as it was, on the same transform) differ; marks the
/// leaves it changed dirty. Does nothing when nothing is masked. Cost: the band, in parallel.
void keepMasked(FieldImage& field, const openvdb::FloatGrid& before);

}  // namespace sculpt
