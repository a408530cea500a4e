// SPDX-License-Identifier: Apache-2.0
#include "core/scan/scan_frame.h"

#include <algorithm>
#include <cctype>
#include <map>

namespace sculpt {

namespace {

std::string lower(std::string text)
{
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return text;
}

}  // namespace

openvdb::Mat4d inLpsMillimetres(const openvdb::Mat4d& worldFromIndex, const openvdb::Vec3d& signs,
                                double millimetresPerUnit)
{
    openvdb::Mat4d lpsFromFile = openvdb::Mat4d::identity();
    for (int a = 0; a < 3; ++a) lpsFromFile[a][a] = signs[a] * millimetresPerUnit;
    return worldFromIndex * lpsFromFile;  // row vectors: the file's world first, then LPS
}

std::optional<openvdb::Vec3d> anatomicalSigns(const std::string& space)
{
    std::string name = lower(space);
    if (name.size() > 5 && name.compare(name.size() - 5, 5, "-time") == 0) name.resize(name.size() - 5);
    static const std::map<std::string, openvdb::Vec3d> kSpaces{{"left-posterior-superior", {1, 1, 1}},
                                                               {"lps", {1, 1, 1}},
                                                               {"right-anterior-superior", {-1, -1, 1}},
                                                               {"ras", {-1, -1, 1}},
                                                               {"left-anterior-superior", {1, -1, 1}},
                                                               {"las", {1, -1, 1}},
                                                               {"rast", {-1, -1, 1}},
                                                               {"last", {1, -1, 1}},
                                                               {"lpst", {1, 1, 1}}};
    const auto found = kSpaces.find(name);
    if (found == kSpaces.end()) return std::nullopt;
    return found->second;
}

std::optional<double> millimetresPer(const std::string& unit)
{
    static const std::map<std::string, double> kUnits{
        {"mm", 1.0},           {"millimeter", 1.0},  {"millimeters", 1.0},  {"millimetre", 1.0}, {"millimetres", 1.0},
        {"um", 1e-3},          {"\xC2\xB5m", 1e-3},  {"micron", 1e-3},      {"microns", 1e-3},   {"micrometer", 1e-3},
        {"micrometers", 1e-3}, {"micrometre", 1e-3}, {"micrometres", 1e-3}, {"m", 1e3},          {"meter", 1e3},
        {"meters", 1e3},       {"metre", 1e3},       {"metres", 1e3},       {"cm", 10.0},        {"centimeter", 10.0},
        {"centimeters", 10.0}, {"centimetre", 10.0}, {"centimetres", 10.0}, {"nm", 1e-6}};
    const auto found = kUnits.find(lower(unit));
    if (found == kUnits.end()) return std::nullopt;
    return found->second;
}

double niftiMillimetresPer(int xyztUnits)
{
    switch (xyztUnits & 0x07) {
    case 1: return 1e3;   // NIFTI_UNITS_METER
    case 3: return 1e-3;  // NIFTI_UNITS_MICRON
    default: return 1.0;  // millimetres, or unknown: millimetres, as every viewer takes them
    }
}

}  // namespace sculpt
