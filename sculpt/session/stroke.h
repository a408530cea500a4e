// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file stroke.h
/// @brief A brush stroke as the user drew it: settings, symmetry and the sampled path.

#include "core/brushes/brush.h"

#include <vector>

namespace sculpt {

/// One sample of the pointer along a stroke.
struct StrokeSample {
    openvdb::Vec3d positionWorld{0.0};             ///< on (or near) the surface
    double pressure = 1.0;                         ///< (0, 1]; 1 for a mouse
    openvdb::Vec3d viewDirection{0.0, 0.0, -1.0};  ///< from the eye into the scene
};

/// Mirror planes through the model's origin: x = 0, y = 0, z = 0.
struct Symmetry {
    bool x = false, y = false, z = false;
    bool any() const { return x || y || z; }
};

struct Stroke {
    BrushSettings brush;
    double spacing = 0.25;  ///< distance between stamps, as a fraction of the radius
    Symmetry symmetry;
    std::vector<StrokeSample> samples;
};

/// Places the stamps of a stroke while it is being drawn: the first at the first sample, then one
/// every spacing x radius of arc length along the sampled polyline (pressure and view
/// interpolated), and on finish() one at the last sample unless a stamp is already there. Each
/// stamp is followed by its mirror images, each chaining to its own previous stamp. A prefix of
/// the samples always yields a prefix of the stamps, so a live stroke stamps as the pointer moves
/// and a replay of its samples stamps the same.
class StrokeStepper {
public:
    /// Uses the stroke's brush radius, spacing and symmetry (not its samples).
    explicit StrokeStepper(const Stroke& stroke);

    /// The stamps due once the path reaches `sample`.
    std::vector<BrushStamp> add(const StrokeSample& sample);
    /// The closing stamp at the last sample, if it is not where the last stamp was.
    std::vector<BrushStamp> finish();

private:
    void emit(const StrokeSample& at, std::vector<BrushStamp>& out);

    double mStep;
    std::vector<openvdb::Vec3d> mSigns;
    bool mStarted = false;
    StrokeSample mLast;
    double mToNext = 0.0;  // arc length from mLast to the next stamp
    openvdb::Vec3d mLastStamp{0.0};
};

/// Every stamp of a finished stroke: its samples through a StrokeStepper.
std::vector<BrushStamp> strokeStamps(const Stroke& stroke);

}  // namespace sculpt
