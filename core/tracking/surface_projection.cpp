// SPDX-License-Identifier: Apache-2.0
#include "core/tracking/surface_projection.h"

#include <cmath>

namespace sculpt {

FieldProbe::FieldProbe(const openvdb::FloatGrid& grid)
    : mAccessor(grid.getConstAccessor()), mTransform(grid.transform()), mVoxelSize(grid.voxelSize()[0])
{}

FieldSample FieldProbe::at(const openvdb::Vec3d& world) const
{
    const openvdb::Vec3d index = mTransform.worldToIndex(world);
    const openvdb::Coord base(int(std::floor(index.x())), int(std::floor(index.y())), int(std::floor(index.z())));
    const openvdb::Vec3d f = index - base.asVec3d();
    // v[i][j][k] is the voxel base + (i - 1, j - 1, k - 1): the cell's corners and their neighbours.
    double v[4][4][4] = {};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k) {
                const bool corner = (i == 0 || i == 3) + (j == 0 || j == 3) + (k == 0 || k == 3) > 1;
                if (!corner) v[i][j][k] = mAccessor.getValue(base.offsetBy(i - 1, j - 1, k - 1));
            }
    FieldSample s;
    const double inv2h = 0.5 / mVoxelSize;
    for (int i = 1; i <= 2; ++i)
        for (int j = 1; j <= 2; ++j)
            for (int k = 1; k <= 2; ++k) {
                const double w =
                    (i == 2 ? f.x() : 1.0 - f.x()) * (j == 2 ? f.y() : 1.0 - f.y()) * (k == 2 ? f.z() : 1.0 - f.z());
                s.phi += w * v[i][j][k];
                s.gradient += w * inv2h *
                              openvdb::Vec3d(v[i + 1][j][k] - v[i - 1][j][k], v[i][j + 1][k] - v[i][j - 1][k],
                                             v[i][j][k + 1] - v[i][j][k - 1]);
            }
    return s;
}

Projection projectOntoSurface(const FieldProbe& probe, const openvdb::Vec3d& world)
{
    const double h = probe.voxelSize();
    openvdb::Vec3d p = world;
    FieldSample s;
    for (int step = 0; step <= kMaxNewtonSteps; ++step) {
        s = probe.at(p);
        if (std::abs(s.phi) < kOnSurfaceVoxels * h) return {p, s.gradient, false};
        const double g2 = s.gradient.lengthSqr();
        if (step == kMaxNewtonSteps || g2 < kMinGradient * kMinGradient) break;
        openvdb::Vec3d move = s.gradient * (s.phi / g2);
        const double length = move.length();
        if (length > h) move *= h / length;
        p -= move;
    }
    return {world, s.gradient, true};
}

}  // namespace sculpt
