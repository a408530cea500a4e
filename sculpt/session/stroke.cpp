// SPDX-License-Identifier: Apache-2.0
#include "sculpt/session/stroke.h"

#include <cmath>

namespace sculpt {

namespace {

StrokeSample lerp(const StrokeSample& a, const StrokeSample& b, double t)
{
    return {a.positionWorld + (b.positionWorld - a.positionWorld) * t, a.pressure + (b.pressure - a.pressure) * t,
            a.viewDirection + (b.viewDirection - a.viewDirection) * t};
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

StrokeStepper::StrokeStepper(const Stroke& stroke)
    : mStep(stroke.spacing * stroke.brush.radiusWorld), mSigns(mirrorSigns(stroke.symmetry))
{}

void StrokeStepper::emit(const StrokeSample& at, std::vector<BrushStamp>& out)
{
    const openvdb::Vec3d previous = mStarted ? mLastStamp : at.positionWorld;
    for (const openvdb::Vec3d& sign : mSigns) {
        out.push_back({at.positionWorld * sign, previous * sign, at.pressure, at.viewDirection * sign});
    }
    mLastStamp = at.positionWorld;
}

std::vector<BrushStamp> StrokeStepper::add(const StrokeSample& sample)
{
    std::vector<BrushStamp> out;
    if (!mStarted) {
        emit(sample, out);
        mStarted = true;
        mLast = sample;
        mToNext = mStep;
        return out;
    }
    const double length = (sample.positionWorld - mLast.positionWorld).length();
    double travelled = 0.0;
    while (length - travelled >= mToNext) {
        travelled += mToNext;
        emit(lerp(mLast, sample, travelled / length), out);
        mToNext = mStep;
    }
    mToNext -= length - travelled;
    mLast = sample;
    return out;
}

std::vector<BrushStamp> StrokeStepper::finish()
{
    std::vector<BrushStamp> out;
    if (mStarted && (mLast.positionWorld - mLastStamp).length() > 1e-9 * mStep) emit(mLast, out);
    return out;
}

std::vector<BrushStamp> strokeStamps(const Stroke& stroke)
{
    StrokeStepper stepper(stroke);
    std::vector<BrushStamp> stamps;
    for (const StrokeSample& sample : stroke.samples) {
        for (BrushStamp& stamp : stepper.add(sample)) stamps.push_back(stamp);
    }
    for (BrushStamp& stamp : stepper.finish()) stamps.push_back(stamp);
    return stamps;
}

}  // namespace sculpt
