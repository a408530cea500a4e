// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file wide_distance.h
/// @brief A shape's signed distance far beyond its narrow band. A narrow band reads its half
///        width everywhere past it, so a distance measured there saturates: a morph whose source
///        lies farther away than the band could not see itself approach. Beyond the band this
///        reads a copy of the shape kCoarsening times coarser (less coarse for a shape that
///        would vanish at that size) whose band is widened until it covers another shape's
///        surface: the true distance wherever that surface can be, at the cost of a coarse grid.

#include "core/base/progress.h"

#include <openvdb/openvdb.h>

namespace sculpt {

class WideDistance {
public:
    static constexpr int kCoarsening = 4;  ///< coarse voxel = 4 band voxels (64x fewer voxels)

    /// The distance of `band`'s zero set over the surface of `cover` (its active voxels within a
    /// voxel of its zero set). The coarse copy is rebuilt from `band`'s surface
    /// (openvdb::tools::levelSetRebuild) and widened by fast sweeping
    /// (openvdb::tools::dilateSdf), doubling its width per round, so it costs about twice its
    /// final size. Both grids must share their transform.
    /// @throws InputError if the coarse band would need more memory than the machine has;
    ///         Cancelled if progress says stop.
    WideDistance(openvdb::FloatGrid::ConstPtr band, const openvdb::FloatGrid& cover, const Progress& progress = {});

    const openvdb::FloatGrid& band() const { return *mBand; }

    /// Reads the distance from one thread (each thread makes its own).
    class Sampler {
    public:
        explicit Sampler(const WideDistance& distance);
        /// Signed distance at `indexPoint` (the band's index space), world units: the band's
        /// trilinear value within the band; beyond it the coarse value, never below the band's
        /// half width, with the band's sign.
        double at(const openvdb::Vec3d& indexPoint);

    private:
        const WideDistance& mDistance;
        openvdb::FloatGrid::ConstAccessor mBand, mCoarse;
    };

private:
    openvdb::FloatGrid::ConstPtr mBand;
    openvdb::FloatGrid::Ptr mCoarse;
    double mHalfWidthWorld;
};

}  // namespace sculpt
