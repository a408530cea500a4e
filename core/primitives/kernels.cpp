// SPDX-License-Identifier: Apache-2.0
#include "core/primitives/kernels.h"

#include "core/base/enum_names.h"

#include <cmath>

namespace sculpt {

namespace {

constexpr EnumNames<KernelType, 3> kKernelNames{{{KernelType::BlobbyMolecule, "blobby-molecule"},
                                                 {KernelType::Metaball, "metaball"},
                                                 {KernelType::SoftObject, "soft-object"}}};

}  // namespace

double Kernel::value(double r) const
{
    if (r >= radius) return 0.0;
    const double q = r / radius, q2 = q * q;
    switch (type) {
    case KernelType::BlobbyMolecule: return strength * std::exp(-9.0 * q2);
    case KernelType::Metaball:
        return q <= 1.0 / 3.0 ? strength * (1.0 - 3.0 * q2) : 1.5 * strength * (1.0 - q) * (1.0 - q);
    case KernelType::SoftObject:
        return strength * (1.0 - 4.0 / 9.0 * q2 * q2 * q2 + 17.0 / 9.0 * q2 * q2 - 22.0 / 9.0 * q2);
    }
    return 0.0;
}

double Kernel::inverse(double iso) const
{
    if (iso >= strength) return 0.0;
    if (iso <= 0.0) return radius;
    double lo = 0.0, hi = radius;  // value(lo) > iso >= value(hi)
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (value(mid) > iso ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

const char* kernelName(KernelType type) { return enumName(kKernelNames, type); }

KernelType kernelFromName(const std::string& name) { return enumFromName(kKernelNames, name, "kernel"); }

}  // namespace sculpt
