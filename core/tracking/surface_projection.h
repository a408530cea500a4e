// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file surface_projection.h
/// @brief A point brought back onto the zero level set by Newton steps along the gradient
///        (Nesme and Bouthors, dynamic triangulation of implicit surfaces).
///
/// phi is read trilinearly and its gradient is the lattice's central differences interpolated
/// trilinearly, so both are continuous and Newton's step p <- p - phi grad / |grad|^2 converges
/// on a distance field in one or two steps. A point is quasi-critical when the steps do not
/// bring |phi| under a hundredth of a voxel, or when |grad phi| falls under one half: on the
/// medial sheet between two lobes (or outside the band, where phi is flat) the gradient gives
/// no direction to follow. It is then left where it was.

#include <openvdb/openvdb.h>

namespace sculpt {

/// phi at a world point (world units) and its gradient (unit length on a distance field).
struct FieldSample {
    double phi = 0.0;
    openvdb::Vec3d gradient{0.0};
};

/// Reads a level-set grid at world points. Holds an accessor: one probe per thread.
class FieldProbe {
public:
    explicit FieldProbe(const openvdb::FloatGrid& grid);

    /// Trilinear phi and the trilinearly interpolated central-difference gradient at `world`.
    /// Cost: 32 voxel look-ups through a cached accessor.
    FieldSample at(const openvdb::Vec3d& world) const;
    double voxelSize() const { return mVoxelSize; }

private:
    openvdb::FloatGrid::ConstAccessor mAccessor;
    const openvdb::math::Transform& mTransform;
    double mVoxelSize;
};

struct Projection {
    openvdb::Vec3d position{0.0};  ///< on the surface, or where it started if quasi-critical
    openvdb::Vec3d gradient{0.0};  ///< grad phi at the last point read
    bool quasiCritical = false;
};

/// Newton steps that stop at |phi| < 0.01 voxel; a step is no longer than a voxel (the band's
/// values are distances only near the surface). At most kMaxNewtonSteps.
Projection projectOntoSurface(const FieldProbe& probe, const openvdb::Vec3d& world);

inline constexpr int kMaxNewtonSteps = 8;
/// |phi| under this many voxels is on the surface.
inline constexpr double kOnSurfaceVoxels = 0.01;
/// |grad phi| under this is the medial sheet, or no band at all.
inline constexpr double kMinGradient = 0.5;

}  // namespace sculpt
