// SPDX-License-Identifier: Apache-2.0
#include "core/scan/largest_component.h"

#include "core/scan/mask_regions.h"

#include <openvdb/tools/LevelSetUtil.h>
#include <openvdb/tools/Prune.h>
#include <openvdb/tree/LeafManager.h>

namespace sculpt {

namespace {

/// The inside and every pocket of outside it encloses: all but the outside that reaches the
/// border of a box one voxel larger than the inside. Counts the pockets.
openvdb::BoolTree::Ptr filledSolid(const openvdb::BoolTree& inside, std::size_t& pockets)
{
    openvdb::CoordBBox box;
    inside.evalActiveVoxelBoundingBox(box);
    box.expand(1);
    auto solid = std::make_shared<openvdb::BoolTree>(false);
    solid->fill(box, true, true);
    openvdb::BoolTree outside(*solid);
    outside.topologyDifference(inside);
    const openvdb::BoolTree::Ptr exterior = connectedRegion(outside, box.min()).tree();  // the box's border is exterior
    outside.topologyDifference(*exterior);
    solid->topologyDifference(*exterior);
    pockets = 0;
    forEachConnectedRegion(outside, [&](const MaskRegion&) { ++pockets; });
    return solid;
}

/// Makes the field's inside exactly `kept`: band voxels on the wrong side leave the band (their
/// distances referred to a surface that is gone), every other value takes kept's side.
void keepOnly(openvdb::FloatTree& tree, const openvdb::BoolTree& kept)
{
    const float background = tree.background();
    openvdb::tree::LeafManager<openvdb::FloatTree> leaves(tree);
    leaves.foreach ([&](openvdb::FloatTree::LeafNodeType& leaf, size_t) {
        const openvdb::tree::ValueAccessor<const openvdb::BoolTree> inKept(kept);
        for (auto it = leaf.beginValueAll(); it; ++it) {
            const bool member = inKept.isValueOn(it.getCoord());
            if (it.isValueOn() && (*it < 0.0f) == member) continue;
            leaf.setValueOff(it.pos(), member ? -background : background);
        }
    });
    const openvdb::tree::ValueAccessor<const openvdb::BoolTree> inKept(kept);
    auto tile = tree.beginValueAll();
    tile.setMaxDepth(openvdb::FloatTree::ValueAllIter::LEAF_DEPTH - 1);  // tiles only
    for (; tile; ++tile) tile.setValue(inKept.isValueOn(tile.getCoord()) ? -background : background);
    openvdb::tools::pruneLevelSet(tree);
}

}  // namespace

LargestComponentReport keepLargestComponent(FieldImage& field, const Progress& progress)
{
    openvdb::FloatTree& tree = field.mutableGrid().tree();
    const auto inside = openvdb::tools::sdfInteriorMask(tree);
    LargestComponentReport report;
    if (inside->empty()) return report;
    sculpt::report(progress, 0.3);
    const openvdb::BoolTree::Ptr solid = filledSolid(*inside, report.cavitiesFilled);
    sculpt::report(progress, 0.6);
    MaskRegion largest;
    openvdb::Index64 largestVoxels = 0;
    forEachConnectedRegion(*solid, [&](const MaskRegion& piece) {
        const openvdb::Index64 voxels = piece.voxelCount();
        if (voxels > largestVoxels) {
            largest = piece;
            largestVoxels = voxels;
        }
        ++report.islandsDropped;
    });
    --report.islandsDropped;        // the largest piece stays
    sculpt::report(progress, 0.9);  // the last chance to stop: the field is unchanged so far
    if (report.islandsDropped == 0 && report.cavitiesFilled == 0) return report;
    keepOnly(tree, *largest.tree());
    field.markDirty(field.allLeaves());
    return report;
}

}  // namespace sculpt
