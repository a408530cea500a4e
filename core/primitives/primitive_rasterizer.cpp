// SPDX-License-Identifier: Apache-2.0
#include "core/primitives/primitive_rasterizer.h"

#include "core/base/errors.h"
#include "core/base/memory_budget.h"
#include "core/base/text_format.h"
#include "core/field/band_rule.h"
#include "core/field/central_difference.h"

#include <openvdb/tools/LevelSetTracker.h>
#include <openvdb/tools/SignedFloodFill.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <map>
#include <memory>

namespace sculpt {

namespace {

using LeafT = openvdb::FloatTree::LeafNodeType;
constexpr int kLeafDim = int(LeafT::DIM);
constexpr int kSamples = kLeafDim + 2;  // the leaf and one voxel around it, for gradients

/// Leaf origins meeting any primitive's influence (grown by `marginVoxels`), each with the
/// primitives that reach it.
std::map<openvdb::Coord, std::vector<int>> leavesToVisit(const PrimitiveSet& set, const openvdb::math::Transform& xform,
                                                         int marginVoxels)
{
    std::map<openvdb::Coord, std::vector<int>> leaves;
    for (int i = 0; i < int(set.primitives().size()); ++i) {
        const openvdb::BBoxd box = set.influence(i);
        const std::string name = describePrimitive(i, set.primitives()[size_t(i)].name);
        requireWithinModelExtent(box, xform.voxelSize()[0], name + "'s influence");
        const openvdb::Coord lo = xform.worldToIndexCellCentered(box.min()).offsetBy(-marginVoxels);
        const openvdb::Coord hi = xform.worldToIndexCellCentered(box.max()).offsetBy(marginVoxels);
        requireMemory(double(openvdb::CoordBBox(lo, hi).volume()) * sizeof(float), name);
        for (const openvdb::Coord& origin : DirtyRegion::leafOriginsIn(openvdb::CoordBBox(lo, hi))) {
            leaves[origin].push_back(i);
        }
    }
    return leaves;
}

/// First-order signed distance in one leaf, from the field sampled on the leaf and its apron.
std::unique_ptr<LeafT> sampleLeaf(const PrimitiveSet& set, const std::vector<int>& nearby,
                                  const openvdb::math::Transform& xform, const openvdb::Coord& origin, float background)
{
    std::array<double, kSamples * kSamples * kSamples> g;
    auto at = [&](int x, int y, int z) -> double& {
        return g[size_t(((x + 1) * kSamples + (y + 1)) * kSamples + (z + 1))];
    };
    const openvdb::Mat4d worldFromIndex = xform.baseMap()->getAffineMap()->getMat4();  // no virtual call per sample
    for (int x = -1; x <= kLeafDim; ++x)
        for (int y = -1; y <= kLeafDim; ++y)
            for (int z = -1; z <= kLeafDim; ++z) {
                const openvdb::Vec3d world = worldFromIndex.transform(origin.offsetBy(x, y, z).asVec3d());
                at(x, y, z) = set.iso() - set.field(world, nearby);
            }
    const double h = xform.voxelSize()[0];
    auto leaf = std::make_unique<LeafT>(origin, background, false);
    for (auto it = leaf->beginValueAll(); it; ++it) {
        const openvdb::Coord c = it.getCoord() - origin;
        const int x = c.x(), y = c.y(), z = c.z();
        const double slope = centralDifference(at, x, y, z).length() / (2.0 * h);
        const double value = at(x, y, z);
        const double distance =
            std::abs(value) < slope * background ? value / slope : (value < 0 ? -background : background);
        const BandValue band = toBand(distance, double(background));
        it.setValue(band.value);
        it.setValueOn(band.active);
    }
    if (leaf->isEmpty() && leaf->getFirstValue() > 0.0f) return nullptr;  // all outside: background
    return leaf;
}

enum class LeafClass { Outside, Inside, Surface };

/// Interval bound of the field over the leaf grown by `marginWorld`: kernels decrease with
/// distance, and a distance varies by at most the half diagonal across the box. A leaf whose
/// grown box lies wholly on one side of the iso-value holds no band voxel.
LeafClass classifyLeaf(const PrimitiveSet& set, const std::vector<int>& nearby, const openvdb::math::Transform& xform,
                       const openvdb::Coord& origin, double marginWorld)
{
    const openvdb::Vec3d centre = xform.indexToWorld(origin.asVec3d() + openvdb::Vec3d(0.5 * (kLeafDim - 1)));
    const double reach = 0.5 * std::sqrt(3.0) * (kLeafDim - 1) * xform.voxelSize()[0] + marginWorld;
    double most = 0.0, least = 0.0;  // least: a lower bound valid for both blending modes
    for (int i : nearby) {
        const Primitive& p = set.primitives()[size_t(i)];
        const double d = p.skeleton.distance(centre);
        most += p.kernel.value(std::max(0.0, d - reach));
        least = std::max(least, p.kernel.value(d + reach));
    }
    if (most < set.iso()) return LeafClass::Outside;
    if (least > set.iso()) return LeafClass::Inside;
    return LeafClass::Surface;
}

}  // namespace

FieldImage rasterizePrimitives(const PrimitiveSet& set, const openvdb::math::Transform& xform, double halfWidthVoxels,
                               const Progress& progress)
{
    const float background = float(xform.voxelSize()[0] * halfWidthVoxels);
    auto grid = makeLevelSetGrid(xform, background);

    const auto visit = leavesToVisit(set, xform, int(std::ceil(halfWidthVoxels)) + 2);
    std::vector<std::pair<openvdb::Coord, const std::vector<int>*>> work;
    for (const auto& [origin, nearby] : visit) work.emplace_back(origin, &nearby);
    std::vector<std::unique_ptr<LeafT>> leaves(work.size());
    std::vector<LeafClass> classes(work.size());
    const double margin = background + xform.voxelSize()[0];
    inBatches(work.size(), progress, 0.0, 0.9, [&](size_t begin, size_t end) {
        tbb::parallel_for(tbb::blocked_range<size_t>(begin, end), [&](const auto& r) {
            for (size_t i = r.begin(); i < r.end(); ++i) {
                classes[i] = classifyLeaf(set, *work[i].second, xform, work[i].first, margin);
                if (classes[i] == LeafClass::Surface)
                    leaves[i] = sampleLeaf(set, *work[i].second, xform, work[i].first, background);
            }
        });
    });
    for (size_t i = 0; i < work.size(); ++i) {
        if (leaves[i]) grid->tree().addLeaf(leaves[i].release());
        if (classes[i] == LeafClass::Inside) grid->tree().addTile(1, work[i].first, -background, false);
    }
    openvdb::tools::signedFloodFill(grid->tree());
    openvdb::tools::LevelSetTracker<openvdb::FloatGrid> tracker(*grid);
    tracker.setSpatialScheme(openvdb::math::FIRST_BIAS);
    tracker.setNormCount(1);
    tracker.normalize();
    tracker.prune();
    return FieldImage(grid);
}

}  // namespace sculpt
