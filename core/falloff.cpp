#include "falloff.h"

#include "errors.h"

#include <array>
#include <cmath>
#include <utility>

namespace sculpt {

namespace {

constexpr std::array<std::pair<Falloff, const char*>, 4> kNames{{
    {Falloff::Smooth, "smooth"}, {Falloff::Sphere, "sphere"}, {Falloff::Sharp, "sharp"}, {Falloff::Constant, "constant"}}};

} // namespace

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

Falloff falloffFromName(const std::string& name)
{
    for (const auto& [falloff, text] : kNames) {
        if (name == text) return falloff;
    }
    throw InputError("unknown falloff \"" + name + "\" (expected smooth, sphere, sharp or constant)");
}

const char* falloffName(Falloff falloff)
{
    for (const auto& [value, text] : kNames) {
        if (value == falloff) return text;
    }
    return "?";
}

} // namespace sculpt
