// SPDX-License-Identifier: Apache-2.0
#include "core/solids/wall_thickness.h"

#include "core/field/central_difference.h"

#include <openvdb/tools/Interpolation.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <tuple>
#include <vector>

namespace sculpt {

namespace {

/// Sphere tracing from `from` along `direction` until phi turns positive: the distance of the
/// crossing, between the last two samples by linear interpolation.
template <typename Accessor>
std::optional<double> distanceToExit(const Accessor& acc, const openvdb::math::Transform& xform,
                                     const openvdb::Vec3d& from, const openvdb::Vec3d& direction, double start,
                                     double farthest, double voxel)
{
    const double smallest = 0.05 * voxel;  // near the wall the steps would shrink forever
    double travelled = start, before = start, phiBefore = -smallest;
    while (travelled <= farthest + voxel) {
        const double phi = openvdb::tools::BoxSampler::sample(acc, xform.worldToIndex(from + direction * travelled));
        if (phi >= 0.0) {
            const double crossing = before + (travelled - before) * (-phiBefore) / (phi - phiBefore);
            return crossing <= farthest ? std::optional<double>(crossing) : std::nullopt;
        }
        before = travelled;
        phiBefore = phi;
        travelled += std::max(-phi, smallest);
    }
    return std::nullopt;
}

/// A deterministic order of points, for ties.
bool lexicographicallyBefore(const openvdb::Vec3d& a, const openvdb::Vec3d& b)
{
    return std::make_tuple(a.x(), a.y(), a.z()) < std::make_tuple(b.x(), b.y(), b.z());
}

}  // namespace

std::optional<double> wallThicknessAt(const openvdb::FloatGrid& grid, const openvdb::Vec3d& surfacePoint,
                                      const openvdb::Vec3d& normal, double farthestWorld)
{
    const double h = grid.transform().voxelSize()[0];
    const auto acc = grid.getConstAccessor();
    // Start half a voxel in: the wall left behind is then half a voxel off, not a crossing.
    return distanceToExit(acc, grid.transform(), surfacePoint, -normal, 0.5 * h, farthestWorld, h);
}

std::optional<double> overhangDegrees(const openvdb::Vec3d& normal, const openvdb::Vec3d& up)
{
    const double down = -normal.dot(up.unitSafe());
    if (!(down > 0.0)) return std::nullopt;
    return std::acos(std::min(1.0, down)) * 180.0 / M_PI;
}

std::optional<ThinnestWall> thinnestWall(const FieldImage& field, double farthestWorld)
{
    const openvdb::FloatGrid& grid = field.grid();
    const double h = field.voxelSize();
    std::vector<const openvdb::FloatTree::LeafNodeType*> leaves;
    for (auto leaf = grid.tree().cbeginLeaf(); leaf; ++leaf) leaves.push_back(leaf.getLeaf());
    tbb::enumerable_thread_specific<ThinnestWall> found([&] { return ThinnestWall{farthestWorld, {}, 0}; });
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, leaves.size()), [&](const auto& range) {
        ThinnestWall& best = found.local();
        const auto acc = grid.getConstAccessor();
        for (std::size_t i = range.begin(); i < range.end(); ++i) {
            for (auto it = leaves[i]->cbeginValueOn(); it; ++it) {
                if (std::abs(*it) > 0.5 * h) continue;
                const openvdb::Vec3d difference = centralDifferenceAt(acc, it.getCoord());
                if (difference.length() < 1e-12) continue;
                const openvdb::Vec3d normal = difference.unitSafe();
                const openvdb::Vec3d foot =
                    closestSurfacePoint(grid.transform().indexToWorld(it.getCoord()), *it, difference);
                ++best.samples;
                const std::optional<double> t =
                    distanceToExit(acc, grid.transform(), foot, -normal, 0.5 * h, best.thickness, h);
                if (t && (*t < best.thickness || (*t == best.thickness && lexicographicallyBefore(foot, best.where))))
                    best = {*t, foot, best.samples};
            }
        }
    });
    ThinnestWall thinnest{farthestWorld, {}, 0};
    bool any = false;
    for (const ThinnestWall& local : found) {
        thinnest.samples += local.samples;
        if (local.thickness < thinnest.thickness ||
            (local.thickness == thinnest.thickness && local.thickness < farthestWorld &&
             lexicographicallyBefore(local.where, thinnest.where))) {
            thinnest.thickness = local.thickness;
            thinnest.where = local.where;
            any = true;
        }
    }
    if (!any) return std::nullopt;
    return thinnest;
}

}  // namespace sculpt
