// SPDX-License-Identifier: Apache-2.0
#include "core/primitives/sdf_rasterizer.h"

#include "core/base/errors.h"
#include "core/base/memory_budget.h"
#include "core/base/text_format.h"
#include "core/field/band_rule.h"

#include <openvdb/tools/SignedFloodFill.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace sculpt {

namespace {

using LeafT = openvdb::FloatTree::LeafNodeType;
constexpr int kLeafDim = int(LeafT::DIM);

void validate(const AnalyticSdf& sdf, double voxelSize, double halfWidthVoxels)
{
    if (!(voxelSize > 0.0) || !std::isfinite(voxelSize)) {
        throw InputError("voxel size must be a positive number (got " + formatNumber(voxelSize) + ")");
    }
    if (!(halfWidthVoxels >= 1.0) || halfWidthVoxels > 64.0) {
        throw InputError("band half width must be between 1 and 64 voxels");
    }
    const openvdb::Vec3d extent = sdf.bounds.extents();
    const double minExtent = std::min({extent.x(), extent.y(), extent.z()});
    if (!(minExtent >= 2.0 * voxelSize)) {
        throw InputError("the " + sdf.description + " is less than two voxels across at voxel size " +
                             formatNumber(voxelSize) + "; choose a finer voxel size",
                         Remedy::FinerVoxelSize);
    }
    const double maxIndex = std::max(sdf.bounds.min().length(), sdf.bounds.max().length()) / voxelSize;
    if (!(maxIndex < double(1 << 28))) {
        throw InputError("the " + sdf.description + " spans too many voxels for a grid");
    }
    // Band voxels ~ area / h^2 * (2 * half width); leaves along a curved surface are about half full.
    const double bandVoxels = sdf.surfaceArea / (voxelSize * voxelSize) * 2.0 * halfWidthVoxels;
    requireMemory(bandVoxels * sizeof(float) * 2.5, "the " + sdf.description);
}

/// Origins of the leaves that may contain band voxels, sorted.
std::vector<openvdb::Coord> candidateLeaves(const AnalyticSdf& sdf, const openvdb::math::Transform& xform,
                                            double bandWorld)
{
    const int margin = int(std::ceil(bandWorld / xform.voxelSize()[0])) + 1;
    openvdb::Coord lo = xform.worldToIndexNodeCentered(sdf.bounds.min()).offsetBy(-margin);
    openvdb::Coord hi = xform.worldToIndexNodeCentered(sdf.bounds.max()).offsetBy(margin);
    lo = DirtyRegion::leafOriginOf(lo);
    hi = DirtyRegion::leafOriginOf(hi);
    const double halfDiagonal = std::sqrt(3.0) * 0.5 * (kLeafDim - 1) * xform.voxelSize()[0];

    const int slabs = (hi.x() - lo.x()) / kLeafDim + 1;
    tbb::enumerable_thread_specific<std::vector<openvdb::Coord>> found;
    tbb::parallel_for(tbb::blocked_range<int>(0, slabs), [&](const auto& r) {
        auto& local = found.local();
        for (int slab = r.begin(); slab < r.end(); ++slab) {
            const int x = lo.x() + slab * kLeafDim;
            for (int y = lo.y(); y <= hi.y(); y += kLeafDim) {
                for (int z = lo.z(); z <= hi.z(); z += kLeafDim) {
                    const openvdb::Coord origin(x, y, z);
                    const openvdb::Vec3d centre = xform.indexToWorld(origin.asVec3d() + 0.5 * (kLeafDim - 1));
                    if (std::abs(sdf.distance(centre)) <= bandWorld + halfDiagonal) {
                        local.push_back(origin);
                    }
                }
            }
        }
    });
    std::vector<openvdb::Coord> origins;
    for (const auto& local : found) origins.insert(origins.end(), local.begin(), local.end());
    std::sort(origins.begin(), origins.end());
    return origins;
}

/// One leaf of samples: band voxels active with their distance, others +-background.
std::unique_ptr<LeafT> sampleLeaf(const AnalyticSdf& sdf, const openvdb::math::Transform& xform,
                                  const openvdb::Coord& origin, float background)
{
    auto leaf = std::make_unique<LeafT>(origin, background, false);
    for (auto it = leaf->beginValueAll(); it; ++it) {
        const BandValue band = toBand(sdf.distance(xform.indexToWorld(it.getCoord())), double(background));
        it.setValue(band.value);
        it.setValueOn(band.active);
    }
    if (leaf->isEmpty()) return nullptr;
    return leaf;
}

}  // namespace

FieldImage rasterizeSdf(const AnalyticSdf& sdf, double voxelSize, double halfWidthVoxels)
{
    validate(sdf, voxelSize, halfWidthVoxels);
    auto grid = makeLevelSetGrid(voxelSize, halfWidthVoxels);
    const float background = grid->background();

    const auto origins = candidateLeaves(sdf, grid->transform(), background);
    std::vector<std::unique_ptr<LeafT>> leaves(origins.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, origins.size()), [&](const auto& r) {
        for (size_t i = r.begin(); i < r.end(); ++i) {
            leaves[i] = sampleLeaf(sdf, grid->transform(), origins[i], background);
        }
    });
    auto& tree = grid->tree();
    for (auto& leaf : leaves) {
        if (leaf) tree.addLeaf(leaf.release());
    }
    openvdb::tools::signedFloodFill(tree);
    return FieldImage(grid);
}

}  // namespace sculpt
