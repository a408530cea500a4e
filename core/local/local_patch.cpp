#include "core/local/local_patch.h"

#include "core/field/band_rule.h"
#include "core/field/central_difference.h"
#include "core/field/leaf_journal.h"
#include "core/local/band_redistance.h"
#include "core/local/speck_removal.h"

#include <algorithm>
#include <cmath>

namespace sculpt {

namespace {

using LeafT = openvdb::FloatTree::LeafNodeType;

}  // namespace

int substepsFor(double motionWorld, double voxelSize)
{
    return std::max(1, int(std::ceil(std::abs(motionWorld) / voxelSize - 1e-9)));
}

openvdb::Vec3d closestSurfacePointAt(const openvdb::FloatGrid::ConstAccessor& acc, const openvdb::Coord& ijk,
                                     const openvdb::math::Transform& xform)
{
    return closestSurfacePoint(xform.indexToWorld(ijk), acc.getValue(ijk), centralDifferenceAt(acc, ijk));
}

std::vector<openvdb::Coord> leavesMeeting(const openvdb::FloatGrid& grid, const Capsule& region)
{
    const auto& xform = grid.transform();
    const double h = xform.voxelSize()[0];
    openvdb::BBoxd box(openvdb::math::minComponent(region.from, region.to),
                       openvdb::math::maxComponent(region.from, region.to));
    box.expand(region.radius);
    const openvdb::Coord lo = xform.worldToIndexCellCentered(box.min());
    const openvdb::Coord hi = xform.worldToIndexCellCentered(box.max());
    // A leaf meets the capsule if its centre is within radius + half its diagonal (conservative).
    const double leafHalfDiagonal = 0.5 * std::sqrt(3.0) * (LeafT::DIM - 1) * h;
    const Capsule reach = region.grownBy(leafHalfDiagonal);
    std::vector<openvdb::Coord> origins;
    for (const openvdb::Coord& origin : DirtyRegion::leafOriginsIn(openvdb::CoordBBox(lo, hi))) {
        const openvdb::Vec3d centre = xform.indexToWorld(origin.asVec3d() + openvdb::Vec3d(0.5 * (LeafT::DIM - 1)));
        if (reach.contains(centre)) origins.push_back(origin);
    }
    return origins;
}

namespace {

/// A small grid reproducing `grid` exactly on the given leaf positions (leaves and tiles).
openvdb::FloatGrid::Ptr extractLeaves(const openvdb::FloatGrid& grid, const std::vector<openvdb::Coord>& origins)
{
    auto sub = makeLevelSetGrid(grid.transform(), grid.background());
    auto acc = grid.getConstAccessor();
    for (const auto& origin : origins) {
        if (const LeafT* leaf = acc.probeConstLeaf(origin)) {
            sub->tree().addLeaf(new LeafT(*leaf));
        } else {
            sub->tree().addTile(1, origin, acc.getValue(origin), false);
        }
    }
    return sub;
}

}  // namespace

LocalPatch::LocalPatch(const FieldImage& field, const Capsule& region)
    : mRegion(region), mInnerLeaves(leavesMeeting(field.grid(), region)),
      mField(
          extractLeaves(field.grid(), leavesMeeting(field.grid(), region.grownBy(kMarginVoxels * field.voxelSize()))),
          field.units())
{}

void LocalPatch::redistance()
{
    redistanceBand(mField.mutableGrid(), mRegion.grownBy(kRedistanceReachVoxels * mField.voxelSize()));
}

void LocalPatch::writeLeafValues(const std::vector<openvdb::Coord>& origins,
                                 const std::vector<std::array<float, LeafT::SIZE>>& values,
                                 const std::vector<char>& changed)
{
    openvdb::FloatGrid& grid = mField.mutableGrid();
    const float background = grid.background();
    auto acc = grid.getAccessor();
    for (size_t i = 0; i < origins.size(); ++i) {
        if (!changed[i]) continue;
        LeafT* leaf = acc.touchLeaf(origins[i]);
        for (openvdb::Index k = 0; k < LeafT::SIZE; ++k) {
            if (values[i][k] == leaf->getValue(k)) continue;
            setBandValue(*leaf, k, toBand(values[i][k], background));
        }
    }
}

void LocalPatch::offsetSurface(const FalloffBall& ball, double amountWorld)
{
    const auto& xform = mField.grid().transform();
    const int n = substepsFor(amountWorld, mField.voxelSize());
    for (int i = 0; i < n; ++i) {
        remapActive(Capsule::ball(ball.centreWorld, ball.radiusWorld), [&](const openvdb::Coord& ijk,
                                                                           const ConstAccessor& acc) {
            return acc.getValue(ijk) - amountWorld / n * ball.weightAt(closestSurfacePointAt(acc, ijk, xform));
        });
        redistance();
    }
}

DirtyRegion LocalPatch::commit(FieldImage& target, LeafJournal* journal)
{
    openvdb::FloatGrid& grid = target.mutableGrid();
    const Capsule region = mRegion.inIndexSpace(grid.transform());
    removeSpecks(mField.mutableGrid(), region, mInnerLeaves);
    auto acc = grid.getAccessor();
    auto patchAcc = mField.grid().getConstAccessor();
    DirtyRegion touched;
    std::vector<openvdb::Coord> changed;
    for (const auto& origin : mInnerLeaves) {
        const LeafT* from = patchAcc.probeConstLeaf(origin);
        const LeafT* to = acc.probeConstLeaf(origin);
        if (!from && !to && patchAcc.getValue(origin) == acc.getValue(origin)) continue;  // equal tiles
        changed.clear();
        for (auto ijk = openvdb::CoordBBox::createCube(origin, LeafT::DIM).begin(); ijk; ++ijk) {
            if (!region.contains((*ijk).asVec3d())) continue;
            const openvdb::Index k = LeafT::coordToOffset(*ijk);
            const float value = from ? from->getValue(k) : patchAcc.getValue(*ijk);
            const bool active = from ? from->isValueOn(k) : patchAcc.isValueOn(*ijk);
            if (to ? value != to->getValue(k) || active != to->isValueOn(k)
                   : value != acc.getValue(*ijk) || active != acc.isValueOn(*ijk)) {
                changed.push_back(*ijk);
            }
        }
        if (changed.empty()) continue;
        if (journal) journal->save(grid.tree(), origin);
        LeafT* leaf = acc.touchLeaf(origin);
        for (const auto& ijk : changed) {
            const float value = patchAcc.getValue(ijk);
            if (patchAcc.isValueOn(ijk)) {
                leaf->setValueOn(ijk, value);
            } else {
                leaf->setValueOff(ijk, value);
            }
        }
        touched.addVoxel(origin);
    }
    target.markDirty(touched);
    return touched;
}

}  // namespace sculpt
