// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file model_filter.h
/// @brief Whole-model filters, the same from the window (Filters menu, run as a job) and the
///        command line (`sculpt smooth`, `offset`, `hollow`, `islands`): smoothing by
///        mean-curvature flow, offsetting along the normal, hollowing into a shell with drain
///        holes, removing small islands; on a copy, refused if nothing of the model remains.

#include "core/base/progress.h"
#include "core/field/field_image.h"
#include "core/solids/hollow.h"

#include <string>

namespace sculpt {

/// More smoothing than this is a mistake, not a look: 10,000 iterations flatten any model.
inline constexpr int kMaxSmoothIterations = 10000;

struct ModelFilter {
    enum class Kind { Smooth, Offset, Hollow, RemoveIslands };
    Kind kind = Kind::Smooth;
    int iterations = 10;         ///< smooth: stable steps (dt = h^2 / 6)
    bool keepVolume = false;     ///< smooth: hold the mesh volume
    double distanceWorld = 1.0;  ///< offset: > 0 grows
    HollowOptions hollow{};      ///< hollow: the shell
    bool drain = true;           ///< hollow: a drain hole under each cavity
    double drainRadiusWorld = 1.0;
    openvdb::Vec3d up{0.0, 0.0, 1.0};  ///< hollow: the print direction
    double minIslandVolume = 1.0;      ///< remove islands: those of less volume go
};

/// "smooth 10 (keep volume)", "offset +1.5", "hollow 2", "remove islands under 1": what the
/// history shows.
std::string filterLabel(const ModelFilter& filter);

/// `field` filtered. Taken by value: pass a deepCopy() to keep yours untouched.
/// @throws InputError naming `source`: iterations outside 1..kMaxSmoothIterations, a distance
///         not finite or larger than the model, or nothing of the model left; Cancelled if
///         progress says stop.
FieldImage applyFilter(FieldImage field, const ModelFilter& filter, const std::string& source,
                       const Progress& progress = {});

/// @throws InputError naming `source` if `field` encloses less than a voxel after `operation`.
void refuseEmptyResult(const FieldImage& field, const std::string& source, const std::string& operation);

}  // namespace sculpt
