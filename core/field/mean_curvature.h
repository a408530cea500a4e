// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file mean_curvature.h
/// @brief The mean curvature of a sampled distance field by central differences: what the
///        smoothing flow moves by and what a cavity mask selects.

namespace sculpt {

/// kappa |grad phi| at lattice point (x, y, z) of a sampler `at(x, y, z)` with voxel size 1 / invH,
/// kappa = div(grad phi / |grad phi|): 2 / r on a sphere of radius r (phi negative inside),
/// negative in a hollow. Zero where the gradient vanishes. On a distance field |grad phi| = 1, so
/// this is kappa itself.
template <typename Sampler>
double curvatureNormGrad(const Sampler& at, int x, int y, int z, double invH)
{
    const double f = at(x, y, z);
    const double dx = 0.5 * (at(x + 1, y, z) - at(x - 1, y, z)), dy = 0.5 * (at(x, y + 1, z) - at(x, y - 1, z)),
                 dz = 0.5 * (at(x, y, z + 1) - at(x, y, z - 1));
    const double dxx = at(x + 1, y, z) - 2 * f + at(x - 1, y, z), dyy = at(x, y + 1, z) - 2 * f + at(x, y - 1, z),
                 dzz = at(x, y, z + 1) - 2 * f + at(x, y, z - 1);
    const double dxy = 0.25 * (at(x + 1, y + 1, z) - at(x + 1, y - 1, z) - at(x - 1, y + 1, z) + at(x - 1, y - 1, z));
    const double dxz = 0.25 * (at(x + 1, y, z + 1) - at(x + 1, y, z - 1) - at(x - 1, y, z + 1) + at(x - 1, y, z - 1));
    const double dyz = 0.25 * (at(x, y + 1, z + 1) - at(x, y + 1, z - 1) - at(x, y - 1, z + 1) + at(x, y - 1, z - 1));
    const double g2 = dx * dx + dy * dy + dz * dz;
    if (g2 < 1e-12) return 0.0;
    const double num = dx * dx * (dyy + dzz) + dy * dy * (dxx + dzz) + dz * dz * (dxx + dyy) -
                       2.0 * (dx * dy * dxy + dx * dz * dxz + dy * dz * dyz);
    return num / g2 * invH * invH;  // differences carry h: num ~ h^4, g2 ~ h^2
}

}  // namespace sculpt
