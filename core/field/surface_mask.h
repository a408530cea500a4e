// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file surface_mask.h
/// @brief Reading the field's mask where an edit lands, and holding the share of the edit it holds.
///
/// The mask (FieldImage::mask) belongs to the surface but lives on the field's voxels: painting
/// gives each voxel the mask of its closest surface point (masks/mask_edit.h), so the whole band
/// under a masked patch of surface is held alike, and an edit reads each voxel's own value m.
/// Reading it there, not again at a closest point the edit may be moving, keeps the voxels held
/// the same from one step of an edit to the next. An edit that would take a voxel from v to v'
/// leaves it at v + (1 - m)(v' - v): every speed times (1 - m). Where m = 1 the voxel keeps v
/// bit for bit; where m = 0 (or nothing is stored) it takes v' bit for bit.

#include "core/field/band_rule.h"
#include "core/field/field_image.h"

#include <openvdb/openvdb.h>

#include <algorithm>
#include <cmath>

namespace sculpt {

/// Reads a mask, one voxel at a time. Holds an accessor: one reader per thread.
class MaskReader {
public:
    explicit MaskReader(const openvdb::FloatGrid& mask) : mMask(mask.getConstAccessor()) {}
    /// The voxel's mask, clamped to [0, 1]; a value that is not a number (a file's) frees the voxel.
    double at(const openvdb::Coord& ijk) const
    {
        const double m = mMask.getValue(ijk);
        return std::isfinite(m) ? std::clamp(m, 0.0, 1.0) : 0.0;
    }

private:
    openvdb::FloatGrid::ConstAccessor mMask;
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
