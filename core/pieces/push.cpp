// SPDX-License-Identifier: Apache-2.0
#include "core/pieces/push.h"

#include "core/field/placed_box.h"
#include "core/pieces/lattice_transfer.h"

#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/LevelSetMeasure.h>
#include <openvdb/tools/LevelSetRebuild.h>
#include <openvdb/tree/LeafManager.h>

#include <algorithm>
#include <cmath>

namespace sculpt {

namespace {

constexpr int kMaxSecantSteps = 12;
/// The falloff's reach in voxels at least: a narrower one would heap the material into a ridge.
constexpr double kLeastReachVoxels = 4.0;

double volumeOf(const openvdb::FloatGrid& grid) { return openvdb::tools::levelSetVolume(grid); }

/// The deepest the pusher reaches into the pushed piece: the largest -phi of either at a voxel
/// inside both, world units.
double deepest(const openvdb::FloatGrid& pushed, const openvdb::FloatGrid& pusher)
{
    const auto other = pusher.getConstAccessor();
    double depth = 0.0;
    for (auto v = pushed.tree().cbeginValueOn(); v; ++v) {
        const float q = other.getValue(v.getCoord());
        if (*v < 0.0f && q < 0.0f) depth = std::max(depth, double(std::min(-*v, -q)));
    }
    return depth;
}

/// The pushed field swollen by `swell` under the falloff and cut by the pusher (same lattice).
openvdb::FloatGrid::Ptr dented(const openvdb::FloatGrid& wide, const openvdb::FloatGrid& pusher, double swell,
                               double reach)
{
    openvdb::FloatGrid::Ptr out = wide.deepCopy();
    // Leaf by leaf, each with its own accessor: every voxel's value is its own, whatever the
    // threads (tools::foreach with a shared accessor's copies gave other results run to run).
    openvdb::tree::LeafManager<openvdb::FloatTree> leaves(out->tree());
    leaves.foreach ([&](openvdb::FloatTree::LeafNodeType& leaf, std::size_t) {
        const openvdb::tree::ValueAccessor<const openvdb::FloatTree, /*IsSafe=*/false> other(pusher.tree());
        for (auto v = leaf.beginValueOn(); v; ++v) {
            const double q = other.getValue(v.getCoord()), w = std::exp(-(q / reach) * (q / reach));
            v.setValue(float(std::max(double(*v) - swell * w, -q)));
        }
    });
    return out;
}

}  // namespace

PushReport pushAside(FieldImage& pushed, const openvdb::Mat4d& pushedPlacement, const FieldImage& pusher,
                     const openvdb::Mat4d& pusherPlacement, double tolerance)
{
    const double h = pushed.voxelSize();
    const FieldImage narrow = onLatticeOf(pusher, pusherPlacement, pushed, pushedPlacement, pushed.halfWidthVoxels());
    PushReport report;
    report.volumeBefore = volumeOf(pushed.grid());
    const double depth = deepest(pushed.grid(), narrow.grid());
    if (depth <= 0.0) {
        report.volumeAfter = report.volumeBefore;
        return report;
    }
    // Wide bands: the falloff reaches 3 R from the pusher, the swollen surface leaves the old band.
    const double reach = std::max(kLeastReachVoxels * h, 2.0 * depth);
    const double band = 3.0 * reach / h + 2.0;
    const FieldImage wideP = onLatticeOf(pusher, pusherPlacement, pushed, pushedPlacement, band);
    const openvdb::FloatGrid::Ptr wide =
        openvdb::tools::levelSetRebuild(pushed.grid(), 0.0f, float(band), float(band), &pushed.grid().transform());
    // The result as it will be kept (its band rebuilt), so that its volume is the one solved for.
    const auto settled = [&](double swell) {
        return openvdb::tools::levelSetRebuild(*dented(*wide, wideP.grid(), swell, reach), 0.0f,
                                               float(pushed.halfWidthVoxels()), float(pushed.halfWidthVoxels()));
    };
    const auto missing = [&](double swell) { return volumeOf(*settled(swell)) - report.volumeBefore; };
    // Secant from no swell (the bare cut) and a swell of the dent's depth.
    double s0 = 0.0, f0 = missing(0.0), s1 = depth, f1 = missing(depth);
    report.dent = -f0;
    while (report.iterations < kMaxSecantSteps && std::abs(f1) > tolerance * report.volumeBefore && f1 != f0) {
        const double s2 = s1 - f1 * (s1 - s0) / (f1 - f0);
        s0 = s1, f0 = f1, s1 = std::max(0.0, s2), f1 = missing(s1);
        ++report.iterations;
    }
    openvdb::FloatGrid::Ptr result = settled(s1);
    result->setName(pushed.grid().getName());
    result->setTransform(pushed.grid().transform().copy());
    pushed.swapGrid(result);
    report.swell = s1;
    report.volumeAfter = volumeOf(pushed.grid());
    return report;
}

DirtyRegion keepOut(FieldImage& field, const DirtyRegion& leaves, const KeepOut& other)
{
    DirtyRegion changed;
    openvdb::CoordBBox otherBox;
    if (!other.field.grid().tree().evalActiveVoxelBoundingBox(otherBox)) return changed;
    const openvdb::math::Transform& xform = field.grid().transform();
    const openvdb::math::Transform& otherXform = other.field.grid().transform();
    const openvdb::BBoxd otherWorld = otherXform.indexToWorld(otherBox);
    openvdb::FloatGrid& grid = field.mutableGrid();
    const openvdb::tools::GridSampler<openvdb::FloatGrid::ConstAccessor, openvdb::tools::BoxSampler> phiOther(
        other.field.grid().getConstAccessor(), otherXform);
    for (const openvdb::Coord& origin : leaves.leafOrigins()) {
        // The leaf's box where the other stands: skipped if it misses the other's band.
        const openvdb::BBoxd own = xform.indexToWorld(openvdb::CoordBBox::createCube(origin, 8));
        if (!placedBox(own, other.toOther).hasOverlap(otherWorld)) continue;
        openvdb::FloatTree::LeafNodeType* leaf = grid.tree().probeLeaf(origin);
        if (!leaf) continue;
        for (auto v = leaf->beginValueOn(); v; ++v) {
            const openvdb::Vec3d q = other.toOther.transform(xform.indexToWorld(v.getCoord()));
            const float cut = -phiOther.wsSample(q);
            if (cut > *v) {
                v.setValue(cut);
                changed.addVoxel(v.getCoord());
            }
        }
    }
    field.markDirty(changed);
    return changed;
}

}  // namespace sculpt
