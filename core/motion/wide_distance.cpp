// SPDX-License-Identifier: Apache-2.0
#include "core/motion/wide_distance.h"

#include "core/base/memory_budget.h"

#include <openvdb/tools/FastSweeping.h>
#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/LevelSetRebuild.h>
#include <openvdb/tree/LeafManager.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>

namespace sculpt {

namespace {

using ConstLeafRange = openvdb::tree::LeafManager<const openvdb::FloatTree>::LeafRange;
constexpr int kCoarseHalfWidthVoxels = 3;

/// True if a voxel of `cover` within a voxel of its surface falls outside `coarse`'s active set.
bool leavesSurfaceUncovered(const openvdb::FloatGrid& cover, const openvdb::FloatGrid& coarse)
{
    const float h = float(cover.voxelSize()[0]);
    openvdb::tree::LeafManager<const openvdb::FloatTree> leaves(cover.tree());
    return tbb::parallel_reduce(
        leaves.leafRange(), false,
        [&](const ConstLeafRange& r, bool found) {
            auto acc = coarse.getConstAccessor();
            for (auto leaf = r.begin(); leaf && !found; ++leaf) {
                for (auto it = leaf->cbeginValueOn(); it && !found; ++it) {
                    if (std::abs(*it) >= h) continue;
                    const openvdb::Vec3d world = cover.indexToWorld(it.getCoord());
                    found = !acc.isValueOn(coarse.transform().worldToIndexCellCentered(world));
                }
            }
            return found;
        },
        [](bool a, bool b) { return a || b; });
}

/// Coarse voxels across the bounding box of both grids: no distance needs a wider band.
int spanVoxels(const openvdb::FloatGrid& a, const openvdb::FloatGrid& b, const openvdb::math::Transform& coarse)
{
    openvdb::BBoxd box = a.transform().indexToWorld(a.evalActiveVoxelBoundingBox());
    box.expand(b.transform().indexToWorld(b.evalActiveVoxelBoundingBox()));
    return int(std::ceil(box.extents().length() / coarse.voxelSize()[0]));
}

bool hasInside(const openvdb::FloatGrid& grid)
{
    for (auto it = grid.cbeginValueOn(); it; ++it) {
        if (*it < 0.0f) return true;
    }
    return false;
}

/// The shape rebuilt kCoarsening times coarser, or less coarse where it would vanish at that
/// size (a wire, a thin ring): widening the band by a sweep needs an inside.
openvdb::FloatGrid::Ptr coarseCopy(const openvdb::FloatGrid& band)
{
    for (int factor = WideDistance::kCoarsening;; factor /= 2) {
        auto transform = band.transform().copy();
        transform->preScale(double(factor));
        auto coarse = openvdb::tools::levelSetRebuild(band, 0.0f, float(kCoarseHalfWidthVoxels), transform.get());
        if (factor == 1 || hasInside(*coarse)) return coarse;
    }
}

}  // namespace

WideDistance::WideDistance(openvdb::FloatGrid::ConstPtr band, const openvdb::FloatGrid& cover, const Progress& progress)
    : mBand(std::move(band)), mHalfWidthWorld(mBand->background())
{
    mCoarse = coarseCopy(*mBand);
    const int maxHalfWidth = hasInside(*mCoarse) ? spanVoxels(*mBand, cover, mCoarse->transform()) : 0;
    int halfWidth = kCoarseHalfWidthVoxels;
    while (halfWidth < maxHalfWidth && leavesSurfaceUncovered(cover, *mCoarse)) {
        const int dilation = std::min(halfWidth, maxHalfWidth - halfWidth);
        // The sweep holds the grid, its copy and a mask: about three grids of the new width.
        const double grownVoxels = double(mCoarse->activeVoxelCount()) * (halfWidth + dilation) / halfWidth;
        requireMemory(3.0 * grownVoxels * sizeof(float), "the target's distance beyond its band");
        mCoarse = openvdb::tools::dilateSdf(*mCoarse, dilation);
        halfWidth += dilation;
        report(progress, double(halfWidth) / maxHalfWidth);
    }
}

WideDistance::Sampler::Sampler(const WideDistance& distance)
    : mDistance(distance), mBand(distance.mBand->getConstAccessor()), mCoarse(distance.mCoarse->getConstAccessor())
{}

double WideDistance::Sampler::at(const openvdb::Vec3d& indexPoint)
{
    const double near = openvdb::tools::BoxSampler::sample(mBand, indexPoint);
    const double w = mDistance.mHalfWidthWorld;
    if (std::abs(near) < w) return near;
    const openvdb::Vec3d coarseIndex = mDistance.mCoarse->worldToIndex(mDistance.mBand->indexToWorld(indexPoint));
    const double far = std::max(w, std::abs(double(openvdb::tools::BoxSampler::sample(mCoarse, coarseIndex))));
    return near < 0.0 ? -far : far;
}

}  // namespace sculpt
