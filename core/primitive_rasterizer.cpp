#include "primitive_rasterizer.h"

#include "memory_budget.h"

#include <openvdb/tools/LevelSetTracker.h>
#include <openvdb/tools/SignedFloodFill.h>

#include <tbb/parallel_for.h>

#include <map>
#include <memory>

namespace sculpt {

namespace {

using LeafT = openvdb::FloatTree::LeafNodeType;
constexpr int kLeafDim = int(LeafT::DIM);
constexpr int kSamples = kLeafDim + 2;  // the leaf and one voxel around it, for gradients

/// Leaf origins meeting any primitive's influence (grown by `marginVoxels`), each with the
/// primitives that reach it.
std::map<openvdb::Coord, std::vector<int>> leavesToVisit(const PrimitiveSet& set,
                                                         const openvdb::math::Transform& xform, int marginVoxels)
{
    std::map<openvdb::Coord, std::vector<int>> leaves;
    for (int i = 0; i < int(set.primitives().size()); ++i) {
        const openvdb::BBoxd box = set.influence(i);
        const openvdb::Coord lo = xform.worldToIndexCellCentered(box.min()).offsetBy(-marginVoxels);
        const openvdb::Coord hi = xform.worldToIndexCellCentered(box.max()).offsetBy(marginVoxels);
        requireMemory(double(openvdb::CoordBBox(lo, hi).volume()) * sizeof(float), describePrimitive(i, set.primitives()[size_t(i)].name));
        for (int x = lo.x() & ~(kLeafDim - 1); x <= hi.x(); x += kLeafDim)
            for (int y = lo.y() & ~(kLeafDim - 1); y <= hi.y(); y += kLeafDim)
                for (int z = lo.z() & ~(kLeafDim - 1); z <= hi.z(); z += kLeafDim) leaves[openvdb::Coord(x, y, z)].push_back(i);
    }
    return leaves;
}

/// First-order signed distance in one leaf, from the field sampled on the leaf and its apron.
std::unique_ptr<LeafT> sampleLeaf(const PrimitiveSet& set, const std::vector<int>& nearby,
                                  const openvdb::math::Transform& xform, const openvdb::Coord& origin, float background)
{
    std::array<double, kSamples * kSamples * kSamples> g;
    auto at = [&](int x, int y, int z) -> double& { return g[size_t(((x + 1) * kSamples + (y + 1)) * kSamples + (z + 1))]; };
    for (int x = -1; x <= kLeafDim; ++x)
        for (int y = -1; y <= kLeafDim; ++y)
            for (int z = -1; z <= kLeafDim; ++z) {
                at(x, y, z) = set.iso() - set.field(xform.indexToWorld(origin.offsetBy(x, y, z)), nearby);
            }
    const double h = xform.voxelSize()[0];
    auto leaf = std::make_unique<LeafT>(origin, background, false);
    for (auto it = leaf->beginValueAll(); it; ++it) {
        const openvdb::Coord c = it.getCoord() - origin;
        const int x = c.x(), y = c.y(), z = c.z();
        const openvdb::Vec3d grad(at(x + 1, y, z) - at(x - 1, y, z), at(x, y + 1, z) - at(x, y - 1, z),
                                  at(x, y, z + 1) - at(x, y, z - 1));
        const double slope = grad.length() / (2.0 * h);
        const double value = at(x, y, z);
        const double distance = std::abs(value) < slope * background ? value / slope : (value < 0 ? -background : background);
        if (std::abs(distance) < background) {
            it.setValue(float(distance));
            it.setValueOn(true);
        } else {
            it.setValue(distance < 0 ? -background : background);
        }
    }
    if (leaf->isEmpty() && leaf->getFirstValue() > 0.0f) return nullptr;  // all outside: background
    return leaf;
}

} // namespace

FieldImage rasterizePrimitives(const PrimitiveSet& set, const openvdb::math::Transform& xform, double halfWidthVoxels)
{
    const float background = float(xform.voxelSize()[0] * halfWidthVoxels);
    auto grid = openvdb::FloatGrid::create(background);
    grid->setTransform(xform.copy());
    grid->setGridClass(openvdb::GRID_LEVEL_SET);
    grid->setName("surface");

    const auto visit = leavesToVisit(set, xform, int(std::ceil(halfWidthVoxels)) + 2);
    std::vector<std::pair<openvdb::Coord, const std::vector<int>*>> work;
    for (const auto& [origin, nearby] : visit) work.emplace_back(origin, &nearby);
    std::vector<std::unique_ptr<LeafT>> leaves(work.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, work.size()), [&](const auto& r) {
        for (size_t i = r.begin(); i < r.end(); ++i) leaves[i] = sampleLeaf(set, *work[i].second, xform, work[i].first, background);
    });
    for (auto& leaf : leaves) {
        if (leaf) grid->tree().addLeaf(leaf.release());
    }
    openvdb::tools::signedFloodFill(grid->tree());
    openvdb::tools::LevelSetTracker<openvdb::FloatGrid> tracker(*grid);
    tracker.setNormCount(4);
    tracker.normalize();
    tracker.prune();
    return FieldImage(grid);
}

} // namespace sculpt
