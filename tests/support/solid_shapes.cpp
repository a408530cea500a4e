// SPDX-License-Identifier: Apache-2.0
#include "tests/support/solid_shapes.h"

#include "core/mesh/incremental_mesher.h"
#include "core/primitives/sdf_rasterizer.h"
#include "tests/support/mesh_checks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <utility>
#include <vector>

namespace sculpt::test {

using openvdb::Vec3d;

Topology topologyOf(const FieldImage& field)
{
    const TriangleMesh mesh = meshLevelSet(field);
    const MeshTopology t = meshTopology(mesh);
    return {shellTriangleCounts(mesh).size(), long(t.eulerCharacteristic()), t.closedManifold()};
}

FieldImage ballsAndSpecks()
{
    std::vector<std::pair<Vec3d, double>> balls{{Vec3d(-8, 0, 0), 5.0}, {Vec3d(8, 0, 0), 5.0}};
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(-18.0, 18.0);
    while (balls.size() < 22) {
        const Vec3d p(coordinate(random), coordinate(random), coordinate(random));
        const bool apart = std::all_of(balls.begin(), balls.end(),
                                       [&](const auto& b) { return (p - b.first).length() > b.second + 2.5; });
        if (apart) balls.push_back({p, 0.4});
    }
    AnalyticSdf sdf;
    sdf.distance = [balls](const Vec3d& p) {
        double d = std::numeric_limits<double>::infinity();
        for (const auto& [centre, radius] : balls) d = std::min(d, (p - centre).length() - radius);
        return d;
    };
    sdf.bounds = openvdb::BBoxd(Vec3d(-20.0), Vec3d(20.0));
    sdf.surfaceArea = 2 * 4 * M_PI * 25 + 20 * 4 * M_PI * 0.16;
    sdf.description = "two balls and twenty specks";
    return rasterizeSdf(sdf, 0.2);
}

double boxDistance(const Vec3d& p, const Vec3d& centre, const Vec3d& half)
{
    const Vec3d q(std::abs(p.x() - centre.x()) - half.x(), std::abs(p.y() - centre.y()) - half.y(),
                  std::abs(p.z() - centre.z()) - half.z());
    const Vec3d out(std::max(q.x(), 0.0), std::max(q.y(), 0.0), std::max(q.z(), 0.0));
    return out.length() + std::min(std::max({q.x(), q.y(), q.z()}), 0.0);
}

/// A plate 20 x 20 x 2 (z from -1 to 1) with a fin 0.6 thick and 4 high standing on it at x = 0;
/// its near edge (y < -6) chamfered at 45 degrees underneath.
FieldImage plateWithFin(double h)
{
    AnalyticSdf sdf;
    sdf.distance = [](const Vec3d& p) {
        const double plate = std::max(boxDistance(p, Vec3d(0, 0, 0), Vec3d(10, 10, 1)),
                                      (-(p.y() + 6.0) - (p.z() + 1.0) - 3.0) / std::sqrt(2.0));
        return std::min(plate, boxDistance(p, Vec3d(0, 0, 3), Vec3d(0.3, 8, 2)));
    };
    sdf.bounds = openvdb::BBoxd(Vec3d(-10, -10, -1), Vec3d(10, 10, 5));
    sdf.surfaceArea = 2 * 400 + 80 + 2 * 64;
    sdf.description = "plate with a fin";
    return rasterizeSdf(sdf, h);
}

ViewPrism frontSquare(double x0, double y0, double x1, double y1)
{
    ViewPrism prism;
    prism.viewFromWorld.setTranslation(Vec3d(0.0, 0.0, -100.0));  // the eye at z = 100
    prism.polygon = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
    return prism;
}

}  // namespace sculpt::test
