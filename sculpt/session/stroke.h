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

/// The stamps of a stroke: one every spacing x radius along the sampled polyline (pressure and
/// view interpolated), the first at the first sample, the last at the last; each stamp followed
/// by its mirror images, each mirror image chaining to its own previous stamp.
std::vector<BrushStamp> strokeStamps(const Stroke& stroke);

}  // namespace sculpt
