// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file central_difference.h
/// @brief The central-difference gradient of a sampled field, and the closest surface point it
///        gives a distance field.
///
/// Every stencil in the engine (brushes, velocity extension, volume estimate, rasterizers, the
/// mesher's normals) reads the same six neighbours; this is the one place that says how. The
/// difference is left unscaled, f(x+1) - f(x-1) per axis (2 h grad f): callers that need the
/// gradient divide by 2 h, callers that need a direction normalise it.

#include <openvdb/Types.h>

namespace sculpt {

/// (f(x+1) - f(x-1), f(y+1) - f(y-1), f(z+1) - f(z-1)) for a sampler `at(x, y, z)` on the lattice.
/// Each difference is taken in the sampler's own precision (float samples: float differences).
template <typename Sampler>
openvdb::Vec3d centralDifference(const Sampler& at, int x, int y, int z)
{
    return {at(x + 1, y, z) - at(x - 1, y, z), at(x, y + 1, z) - at(x, y - 1, z), at(x, y, z + 1) - at(x, y, z - 1)};
}

/// The central difference of `grid`'s values around voxel ijk, through an accessor.
template <typename Accessor>
openvdb::Vec3d centralDifferenceAt(const Accessor& acc, const openvdb::Coord& ijk)
{
    return centralDifference([&](int x, int y, int z) { return acc.getValue(ijk.offsetBy(x, y, z)); }, 0, 0, 0);
}

/// The closest surface point to `point` of a distance field that is `phi` there:
/// point - phi n, n = difference / |difference|. `scale` converts phi into the units of `point`
/// (1 for world points, 1 / h for index points). A flat difference (no direction) gives `point`.
inline openvdb::Vec3d closestSurfacePoint(const openvdb::Vec3d& point, double phi, const openvdb::Vec3d& difference,
                                          double scale = 1.0)
{
    const double length = difference.length();
    return length > 1e-12 ? point - difference * (phi * scale / length) : point;
}

}  // namespace sculpt
