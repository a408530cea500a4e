#include "sculpt/session/stroke.h"

#include <cmath>

namespace sculpt {

namespace {

/// Sample interpolated at arc length s along the polyline (whose cumulative lengths are given).
StrokeSample sampleAt(const std::vector<StrokeSample>& samples, const std::vector<double>& lengths, double s)
{
    size_t i = 1;
    while (i + 1 < samples.size() && lengths[i] < s) ++i;
    const double span = lengths[i] - lengths[i - 1];
    const double t = span > 0.0 ? std::clamp((s - lengths[i - 1]) / span, 0.0, 1.0) : 1.0;
    const StrokeSample& a = samples[i - 1];
    const StrokeSample& b = samples[i];
    return {a.positionWorld + (b.positionWorld - a.positionWorld) * t, a.pressure + (b.pressure - a.pressure) * t,
            a.viewDirection + (b.viewDirection - a.viewDirection) * t};
}

/// Points spaced `step` apart along the samples' polyline, first and last included.
std::vector<StrokeSample> resample(const std::vector<StrokeSample>& samples, double step)
{
    if (samples.size() < 2) return samples;
    std::vector<double> lengths(samples.size(), 0.0);
    for (size_t i = 1; i < samples.size(); ++i) {
        lengths[i] = lengths[i - 1] + (samples[i].positionWorld - samples[i - 1].positionWorld).length();
    }
    const double total = lengths.back();
    const int count = std::max(1, int(std::ceil(total / step - 1e-9)));
    std::vector<StrokeSample> out;
    out.reserve(size_t(count) + 1);
    for (int k = 0; k <= count; ++k) out.push_back(sampleAt(samples, lengths, total * k / count));
    return out;
}

/// The sign flips of every mirror image, the identity first.
std::vector<openvdb::Vec3d> mirrorSigns(const Symmetry& symmetry)
{
    std::vector<openvdb::Vec3d> signs;
    for (int mask = 0; mask < 8; ++mask) {
        if (((mask & 1) && !symmetry.x) || ((mask & 2) && !symmetry.y) || ((mask & 4) && !symmetry.z)) continue;
        signs.emplace_back(mask & 1 ? -1.0 : 1.0, mask & 2 ? -1.0 : 1.0, mask & 4 ? -1.0 : 1.0);
    }
    return signs;
}

}  // namespace

std::vector<BrushStamp> strokeStamps(const Stroke& stroke)
{
    const std::vector<StrokeSample> path = resample(stroke.samples, stroke.spacing * stroke.brush.radiusWorld);
    const std::vector<openvdb::Vec3d> signs = mirrorSigns(stroke.symmetry);
    std::vector<BrushStamp> stamps;
    stamps.reserve(path.size() * signs.size());
    for (size_t i = 0; i < path.size(); ++i) {
        const StrokeSample& previous = path[i == 0 ? 0 : i - 1];
        for (const openvdb::Vec3d& sign : signs) {
            stamps.push_back({path[i].positionWorld * sign, previous.positionWorld * sign, path[i].pressure,
                              path[i].viewDirection * sign});
        }
    }
    return stamps;
}

}  // namespace sculpt
