#include "field_kernels.h"

#include "errors.h"

#include <cmath>

namespace sculpt {

double Kernel::value(double r) const
{
    if (r >= radius) return 0.0;
    const double q = r / radius, q2 = q * q;
    switch (type) {
    case KernelType::BlobbyMolecule:
        return strength * std::exp(-9.0 * q2);
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

const char* kernelName(KernelType type)
{
    switch (type) {
    case KernelType::BlobbyMolecule: return "blobby-molecule";
    case KernelType::Metaball: return "metaball";
    case KernelType::SoftObject: return "soft-object";
    }
    return "?";
}

KernelType kernelFromName(const std::string& name)
{
    for (KernelType t : {KernelType::BlobbyMolecule, KernelType::Metaball, KernelType::SoftObject}) {
        if (name == kernelName(t)) return t;
    }
    throw InputError("unknown kernel '" + name + "' (expected blobby-molecule, metaball or soft-object)");
}

} // namespace sculpt
