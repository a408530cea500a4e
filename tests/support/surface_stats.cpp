// SPDX-License-Identifier: Apache-2.0
#include "tests/support/surface_stats.h"

#include "core/mesh/incremental_mesher.h"

#include <openvdb/math/Stencils.h>

#include <algorithm>
#include <limits>

namespace sculpt::test {

RadiusStats surfaceRadius(const FieldImage& field, const openvdb::Vec3d& centre)
{
    const TriangleMesh mesh = meshLevelSet(field);
    RadiusStats r{0.0, std::numeric_limits<double>::max(), 0.0};
    for (const auto& p : mesh.positions) {
        const double d = (openvdb::Vec3d(p[0], p[1], p[2]) - centre).length();
        r.mean += d;
        r.min = std::min(r.min, d);
        r.max = std::max(r.max, d);
    }
    r.mean /= double(mesh.positions.size());
    return r;
}

double curvatureVariance(const FieldImage& field, std::optional<std::pair<openvdb::Vec3d, double>> ball)
{
    openvdb::math::CurvatureStencil<openvdb::FloatGrid> stencil(field.grid());
    double sum = 0.0, sum2 = 0.0;
    std::size_t n = 0;
    const double h = field.voxelSize();
    for (auto it = field.grid().cbeginValueOn(); it; ++it) {
        if (std::abs(*it) > 0.5 * h) continue;
        if (ball && (field.grid().transform().indexToWorld(it.getCoord()) - ball->first).length() > ball->second)
            continue;
        stencil.moveTo(it.getCoord());
        const double k = stencil.meanCurvature();
        sum += k;
        sum2 += k * k;
        ++n;
    }
    const double mean = sum / double(n);
    return sum2 / double(n) - mean * mean;
}

}  // namespace sculpt::test
