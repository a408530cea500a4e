// SPDX-License-Identifier: Apache-2.0
#include "core/local/falloff.h"

#include "core/base/enum_names.h"

#include <algorithm>
#include <cmath>

namespace sculpt {

namespace {

constexpr EnumNames<Falloff, 4> kFalloffNames{{{Falloff::Smooth, "smooth"},
                                               {Falloff::Sphere, "sphere"},
                                               {Falloff::Sharp, "sharp"},
                                               {Falloff::Constant, "constant"}}};

}  // namespace

double falloffWeight(Falloff falloff, double q)
{
    if (!(q < 1.0)) return 0.0;
    q = std::max(q, 0.0);
    switch (falloff) {
    case Falloff::Smooth: return 1.0 - q * q * (3.0 - 2.0 * q);
    case Falloff::Sphere: return std::sqrt(1.0 - q * q);
    case Falloff::Sharp: return (1.0 - q) * (1.0 - q);
    case Falloff::Constant: return 1.0;
    }
    return 0.0;
}

Falloff falloffFromName(const std::string& name) { return enumFromName(kFalloffNames, name, "falloff"); }

const char* falloffName(Falloff falloff) { return enumName(kFalloffNames, falloff); }

}  // namespace sculpt
