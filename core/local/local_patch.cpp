// SPDX-License-Identifier: Apache-2.0
#include "core/local/local_patch.h"

#include "core/field/band_rule.h"
#include "core/field/central_difference.h"
#include "core/field/leaf_journal.h"
#include "core/field/surface_mask.h"
#include "core/local/band_redistance.h"
#include "core/local/speck_removal.h"

#include <algorithm>
#include <cmath>
#include <optional>

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
    const float background = grid.background();
    std::optional<MaskReader> mask;
    if (target.mask()) mask.emplace(*target.mask());
    struct Change {
        openvdb::Coord ijk;
        BandValue value;
    };
    std::vector<std::pair<openvdb::Coord, std::vector<Change>>> edits;
    const auto acc = grid.getConstAccessor();
    const auto patchAcc = mField.grid().getConstAccessor();
    for (const auto& origin : mInnerLeaves) {
        if (!patchAcc.probeConstLeaf(origin) && !acc.probeConstLeaf(origin) &&
            patchAcc.getValue(origin) == acc.getValue(origin))
            continue;  // equal tiles
        std::vector<Change> changes;
        for (auto ijk = openvdb::CoordBBox::createCube(origin, LeafT::DIM).begin(); ijk; ++ijk) {
            if (!region.contains((*ijk).asVec3d())) continue;
            const float old = acc.getValue(*ijk);
            BandValue next{patchAcc.getValue(*ijk), patchAcc.isValueOn(*ijk)};
            if (mask && next.value != old) next = maskedValue(old, next.value, mask->at(*ijk), background);
            if (next.value != old || next.active != acc.isValueOn(*ijk)) changes.push_back({*ijk, next});
        }
        if (!changes.empty()) edits.emplace_back(origin, std::move(changes));
    }
    // Every leaf is saved before any is written: a leaf made in an empty region must not make its
    // neighbours' saved states part of the region it made.
    for (const auto& [origin, changes] : edits)
        if (journal) journal->save(grid.tree(), origin);
    auto write = grid.getAccessor();
    DirtyRegion touched;
    for (const auto& [origin, changes] : edits) {
        LeafT* leaf = write.touchLeaf(origin);
        for (const Change& change : changes) setBandValue(*leaf, change.ijk, change.value);
        touched.addVoxel(origin);
    }
    target.markDirty(touched);
    return touched;
}

}  // namespace sculpt
