// SPDX-License-Identifier: Apache-2.0
/// @file flatten.cpp
/// @brief flatten: the surface under the brush moves part of its way to the least-squares plane
///        through it.

#include "core/brushes/brush_tools.h"
#include "core/local/local_patch.h"

#include <openvdb/math/Mat3.h>

#include <cmath>
#include <optional>
#include <utility>
#include <vector>

namespace sculpt {

namespace {

using openvdb::Vec3d;

struct Plane {
    Vec3d point, normal;  ///< normal points out of the surface
    double distance(const Vec3d& p) const { return normal.dot(p - point); }
};

/// Least-squares plane through the closest surface points of the voxels next to the surface
/// (|phi| < h) under the ball, weighted by the falloff; also the largest distance to it.
std::optional<std::pair<Plane, double>> fitPlane(const openvdb::FloatGrid& grid, const FalloffBall& ball)
{
    const auto& xform = grid.transform();
    const double h = xform.voxelSize()[0];
    const Capsule region = Capsule::ball(ball.centreWorld, ball.radiusWorld);
    const auto acc = grid.getConstAccessor();
    std::vector<std::pair<Vec3d, double>> samples;
    Vec3d outward(0.0);
    for (auto leaf = grid.tree().cbeginLeaf(); leaf; ++leaf) {
        for (auto it = leaf->cbeginValueOn(); it; ++it) {
            if (std::abs(*it) >= h || !region.contains(xform.indexToWorld(it.getCoord()))) continue;
            const Vec3d foot = closestSurfacePointAt(acc, it.getCoord(), xform);
            const double weight = ball.weightAt(foot) * (1.0 - std::abs(*it) / h);
            if (weight <= 0.0) continue;
            samples.emplace_back(foot, weight);
            outward += (xform.indexToWorld(it.getCoord()) - foot) * (weight * (*it >= 0.0f ? 1.0 : -1.0));
        }
    }
    double total = 0.0;
    Vec3d centroid(0.0);
    for (const auto& [p, w] : samples) {
        total += w;
        centroid += p * w;
    }
    if (samples.size() < 3 || !(total > 0.0)) return std::nullopt;
    centroid /= total;
    openvdb::Mat3d covariance = openvdb::Mat3d::zero();
    for (const auto& [p, w] : samples) {
        const Vec3d d = p - centroid;
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) covariance(r, c) += w * d[r] * d[c];
    }
    openvdb::Mat3d vectors;
    Vec3d values;
    if (!openvdb::math::diagonalizeSymmetricMatrix(covariance, vectors, values)) return std::nullopt;
    int smallest = 0;
    for (int k = 1; k < 3; ++k)
        if (values[k] < values[smallest]) smallest = k;
    Vec3d normal = vectors.col(smallest);
    if (normal.dot(outward) < 0.0) normal = -normal;
    Plane plane{centroid, normal};
    double farthest = 0.0;
    for (const auto& sample : samples) farthest = std::max(farthest, std::abs(plane.distance(sample.first)));
    return std::make_pair(plane, farthest);
}

}  // namespace

DirtyRegion flatten(FieldImage& field, const BrushSettings& brush, const BrushStamp& stamp, LeafJournal* journal)
{
    const FalloffBall ball{stamp.centreWorld, brush.radiusWorld, brush.falloff};
    const Capsule region = Capsule::ball(ball.centreWorld, ball.radiusWorld);
    LocalPatch patch(field, region);
    const auto fit = fitPlane(patch.field().grid(), ball);
    if (!fit) return {};  // no surface under the brush
    const auto& [plane, farthest] = *fit;
    patch.approach(ball, brush.strength * stamp.pressure, farthest,
                   [&plane = plane](const Vec3d& foot) { return plane.distance(foot); });
    return patch.commit(field, journal);
}

}  // namespace sculpt
