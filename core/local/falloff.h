// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file falloff.h
/// @brief How strongly a brush acts at a distance from its centre.
///
/// A falloff maps q = |x - centre| / radius in [0, 1] to a weight in [0, 1], 1 at the centre
/// and 0 from q = 1 on:
///   smooth   1 - (3 q^2 - 2 q^3)   (smoothstep: flat at both ends, no visible rim)
///   sphere   sqrt(1 - q^2)         (the profile of a ball)
///   sharp    (1 - q)^2             (a pointed tip, for creases)
///   constant 1                     (the whole ball alike)

#include <openvdb/Types.h>

#include <string>

namespace sculpt {

enum class Falloff { Smooth, Sphere, Sharp, Constant };

/// Weight at q = distance / radius; 0 for q >= 1.
double falloffWeight(Falloff falloff, double q);

/// "smooth", "sphere", "sharp", "constant". @throws InputError for other names.
Falloff falloffFromName(const std::string& name);
const char* falloffName(Falloff falloff);

/// A ball with a falloff: where and how much a brush acts.
struct FalloffBall {
    openvdb::Vec3d centreWorld{0.0};
    double radiusWorld = 1.0;
    Falloff falloff = Falloff::Smooth;

    double weightAt(const openvdb::Vec3d& world) const
    {
        return falloffWeight(falloff, (world - centreWorld).length() / radiusWorld);
    }
};

}  // namespace sculpt
