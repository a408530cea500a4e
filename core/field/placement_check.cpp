// SPDX-License-Identifier: Apache-2.0
#include "core/field/placement_check.h"

#include "core/base/text_format.h"

#include <cmath>

namespace sculpt {

namespace {

double frobenius(const openvdb::Mat3d& m)
{
    double sum = 0.0;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) sum += m(r, c) * m(r, c);
    return std::sqrt(sum);
}

}  // namespace

std::string placementProblem(const openvdb::Mat4d& placement)
{
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            if (!std::isfinite(placement(r, c))) return "it holds a value that is not a finite number";
    if (placement(0, 3) != 0.0 || placement(1, 3) != 0.0 || placement(2, 3) != 0.0 || placement(3, 3) != 1.0)
        return "it is not an affine map (its last column must be 0 0 0 1)";
    const openvdb::Mat3d turn = placement.getMat3();
    const double det = turn.det();
    if (!(det > 0.0)) return det < 0.0 ? "it mirrors the piece" : "it flattens the piece (no volume)";
    const double scale = std::cbrt(det);
    if (scale < 1.0 / kMaxPlacementScale || scale > kMaxPlacementScale)
        return "it scales the piece by " + formatNumber(scale) + " (limit: " + formatNumber(1.0 / kMaxPlacementScale) +
               " to " + formatNumber(kMaxPlacementScale) + ")";
    const double condition = frobenius(turn) * frobenius(turn.inverse());
    if (condition > 3.0 * kMaxPlacementScale)
        return "it stretches the piece unevenly (condition number " + formatNumber(condition) +
               ", limit: " + formatNumber(3.0 * kMaxPlacementScale) + ")";
    if (placement.getTranslation().length() > kMaxPlacementOffset)
        return "it moves the piece " + formatNumber(placement.getTranslation().length()) +
               " away (limit: " + formatNumber(kMaxPlacementOffset) + ")";
    return {};
}

}  // namespace sculpt
