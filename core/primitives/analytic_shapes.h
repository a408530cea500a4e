// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file analytic_shapes.h
/// @brief Exact signed distances of the starting shapes (sphere, box, torus), centred at the
///        origin, and builders that rasterize them into field images.

#include "core/primitives/sdf_rasterizer.h"

namespace sculpt {

/// Sphere of radius `radiusWorld`. Volume 4/3 pi r^3, area 4 pi r^2.
/// @throws InputError if the radius is not positive and finite.
AnalyticSdf sphereSdf(double radiusWorld);

/// Axis-aligned cube of half side `halfSideWorld`. Volume (2a)^3, area 6 (2a)^2.
/// @throws InputError if the half side is not positive and finite.
AnalyticSdf boxSdf(double halfSideWorld);

/// Torus around the z axis: major radius R (centre of the tube), minor radius r (tube).
/// Volume 2 pi^2 R r^2, area 4 pi^2 R r.
/// @throws InputError unless 0 < r < R, both finite.
AnalyticSdf torusSdf(double majorRadiusWorld, double minorRadiusWorld);

/// The starting shape `name` ("sphere", "box" or "torus"; `sculpt new --shape`): `size` is the
/// sphere's radius, the box's half side or the torus's major radius, `minor` the torus's tube
/// radius (0: size / 3). @throws InputError for another name or sizes as above.
AnalyticSdf startingShapeSdf(const std::string& name, double size, double minor = 0.0);

/// Convenience builders: rasterizeSdf(shapeSdf(...), voxelSize, halfWidthVoxels).
FieldImage makeSphere(double radiusWorld, double voxelSize,
                      double halfWidthVoxels = FieldImage::kDefaultHalfWidthVoxels);
FieldImage makeBox(double halfSideWorld, double voxelSize,
                   double halfWidthVoxels = FieldImage::kDefaultHalfWidthVoxels);
FieldImage makeTorus(double majorRadiusWorld, double minorRadiusWorld, double voxelSize,
                     double halfWidthVoxels = FieldImage::kDefaultHalfWidthVoxels);

}  // namespace sculpt
