// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file field_kernels.h
/// @brief Field functions of the distance r to a skeleton (the soft-object literature).
///
/// Every kernel decreases from its strength `a` at r = 0 towards 0; R is the radius of influence.
///  - Blinn's blobby molecule: a exp(-b r^2), with b = 9 / R^2 so that f(R) = a e^-9 (~1e-4 a):
///    negligible beyond R, where it is cut off.
///  - Blinn/Nishimura metaball: a (1 - 3 r^2/R^2) for r <= R/3, 3a/2 (1 - r/R)^2 for r <= R,
///    0 beyond (piecewise quadratic, C1).
///  - Wyvill soft object: a (1 - 4/9 r^6/R^6 + 17/9 r^4/R^4 - 22/9 r^2/R^2) for r <= R, 0 beyond.
/// A lone primitive's surface at iso-value c lies at r = f^-1(c): its thickness.

#include <string>

namespace sculpt {

enum class KernelType { BlobbyMolecule, Metaball, SoftObject };

struct Kernel {
    KernelType type = KernelType::SoftObject;
    double radius = 1.0;    ///< R, radius of influence (world units), > 0
    double strength = 1.0;  ///< a, the value at r = 0, > 0

    /// f(r).
    double value(double r) const;
    /// The r where f(r) = iso, by bisection on [0, R]; 0 if iso >= strength (no surface) and R
    /// if iso <= 0.
    double inverse(double iso) const;
};

/// "blobby-molecule", "metaball", "soft-object".
const char* kernelName(KernelType type);
/// @throws InputError naming the unknown kernel.
KernelType kernelFromName(const std::string& name);

}  // namespace sculpt
