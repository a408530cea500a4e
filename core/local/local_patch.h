// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file local_patch.h
/// @brief A small copy of the field around an edit, worked on alone and written back in place.
///
/// OpenVDB's tracker and filters visit every leaf of the grid they are given, so a
/// local edit copies the leaves near its region into a small grid, edits and redistances that,
/// then writes back only the voxels inside the region: everything outside stays bit for bit, and
/// the cost follows the region, not the model. The copy reaches a margin beyond the region so
/// that the stencils and the redistancing read true values wherever they write.
///
/// The operations below are what every brush is made of: remap the band's values, combine every
/// voxel with a shape, advect by a displacement, offset along the normal. Each changes the copy
/// only inside the region it is given; redistance() afterwards keeps the band a distance field.

#include "core/field/dirty_region.h"
#include "core/field/field_image.h"
#include "core/local/capsule.h"
#include "core/local/falloff.h"

#include <openvdb/tools/Interpolation.h>
#include <openvdb/tree/LeafManager.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <vector>

namespace sculpt {

class LeafJournal;

/// Origins of the leaves of `grid`'s lattice that may hold a voxel inside `region` (conservative).
std::vector<openvdb::Coord> leavesMeeting(const openvdb::FloatGrid& grid, const Capsule& region);

/// Sub-steps needed so that no part of the surface moves more than a voxel at a time: the
/// redistancing between them rebuilds the band one voxel deep.
int substepsFor(double motionWorld, double voxelSize);

/// The closest surface point to voxel ijk, in world space, from central differences.
openvdb::Vec3d closestSurfacePointAt(const openvdb::FloatGrid::ConstAccessor& acc, const openvdb::Coord& ijk,
                                     const openvdb::math::Transform& xform);

class LocalPatch {
public:
    using ConstAccessor = openvdb::FloatGrid::ConstAccessor;

    /// Voxels beyond the region that redistance() rebuilds too: the next sub-step's stencils
    /// read them.
    static constexpr double kRedistanceReachVoxels = 2.0;
    /// Voxels of margin copied beyond the region: what is redistanced plus a WENO5 stencil (3)
    /// and the tracker's dilation, for whole-grid tools run on the copy; one leaf.
    static constexpr double kMarginVoxels = 8.0;

    /// Copies the leaves (and leaf-sized tiles) within `region` grown by the margin.
    LocalPatch(const FieldImage& field, const Capsule& region);

    /// The copy: a field image of its own, for any whole-grid tool (tracker, evolution).
    FieldImage& field() { return mField; }
    const Capsule& region() const { return mRegion; }

    /// Rebuilds the copy's band and |grad phi| = 1 inside the region and a little beyond
    /// (redistanceBand): after each motion of up to a voxel.
    void redistance();

    /// Sets every active voxel inside `region` to value(ijk, frozen), `frozen` reading the values
    /// before the pass (so the order of voxels does not matter); results are clamped to the band.
    /// value: (const Coord&, const ConstAccessor&) -> double. Parallel over leaves.
    template <typename ValueFn>
    void remapActive(const Capsule& region, const ValueFn& value);

    /// Sets every voxel inside `region` (active or not) to combine(world, phi), activating the
    /// ones that enter the band and deactivating those that leave it. Values in parallel, then the
    /// tree's structure in one thread. Tiles of value `keptTile` are skipped: combine never
    /// changes them (the inside, for a union). combine: (const Vec3d& world, float phi) -> double.
    template <typename CombineFn>
    void combineVoxels(const Capsule& region, float keptTile, const CombineFn& combine);

    /// Semi-Lagrangian advection inside `region`: phi(x) <- phi(x - displacement(x)), trilinear.
    /// displacement: (const Vec3d& world) -> Vec3d, world units.
    template <typename DisplacementFn>
    void advect(const Capsule& region, const DisplacementFn& displacement);

    /// Moves the surface inside `ball` along its normal by amountWorld x the falloff at each
    /// voxel's closest surface point (a speed extended along normals keeps the band a distance
    /// field), in sub-steps of at most a voxel, each redistanced.
    void offsetSurface(const FalloffBall& ball, double amountWorld);

    /// Moves the surface inside `ball` a fraction (times the falloff) of its signed distance to
    /// another surface, read at each voxel's closest surface point (> 0: the other surface is
    /// inside, so the surface moves in), in sub-steps of at most a voxel, each redistanced.
    /// `farthest` bounds |distance| under the ball (it sets the sub-steps); the distance is read
    /// afresh at every sub-step, so a curved target is followed, not just its first tangent.
    /// distance: (const Vec3d& world) -> double, called from several threads.
    template <typename DistanceFn>
    void approach(const FalloffBall& ball, double fraction, double farthest, const DistanceFn& distance);

    /// Removes the specks the edit left in the region (removeSpecks), then writes the copy's
    /// voxels inside the region back to `target` (value and active state), saving each leaf in
    /// `journal` before it first changes; marks and returns the changed leaves.
    DirtyRegion commit(FieldImage& target, LeafJournal* journal);

private:
    using LeafT = openvdb::FloatTree::LeafNodeType;

    /// Writes whole leaves of values computed by combineVoxels (those marked changed), each
    /// voxel active where it lies inside the band.
    void writeLeafValues(const std::vector<openvdb::Coord>& origins,
                         const std::vector<std::array<float, LeafT::SIZE>>& values, const std::vector<char>& changed);

    Capsule mRegion;
    std::vector<openvdb::Coord> mInnerLeaves;  // leaves the region meets: the ones commit visits
    FieldImage mField;
};

// ---- implementation of the operations ----

template <typename ValueFn>
void LocalPatch::remapActive(const Capsule& region, const ValueFn& value)
{
    openvdb::FloatGrid& grid = mField.mutableGrid();
    const openvdb::FloatGrid::Ptr frozen = grid.deepCopy();
    const Capsule indexRegion = region.inIndexSpace(grid.transform());
    const float background = grid.background();
    openvdb::tree::LeafManager<openvdb::FloatTree> leaves(grid.tree());
    leaves.foreach ([&](LeafT& leaf, size_t) {
        const ConstAccessor acc = frozen->getConstAccessor();
        for (auto it = leaf.beginValueOn(); it; ++it) {
            if (!indexRegion.contains(it.getCoord().asVec3d())) continue;
            it.setValue(std::clamp(float(value(it.getCoord(), acc)), -background, background));
        }
    });
}

template <typename CombineFn>
void LocalPatch::combineVoxels(const Capsule& region, float keptTile, const CombineFn& combine)
{
    openvdb::FloatGrid& grid = mField.mutableGrid();
    const auto& xform = grid.transform();
    const float background = grid.background();
    const std::vector<openvdb::Coord> origins = leavesMeeting(grid, region);
    const Capsule indexRegion = region.inIndexSpace(xform);
    std::vector<std::array<float, LeafT::SIZE>> values(origins.size());
    std::vector<char> changed(origins.size(), 0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, origins.size()), [&](const auto& range) {
        const ConstAccessor acc = grid.getConstAccessor();
        for (size_t i = range.begin(); i < range.end(); ++i) {
            if (!acc.probeConstLeaf(origins[i]) && acc.getValue(origins[i]) == keptTile) continue;
            for (auto ijk = openvdb::CoordBBox::createCube(origins[i], LeafT::DIM).begin(); ijk; ++ijk) {
                const float old = acc.getValue(*ijk);
                const float value =
                    indexRegion.contains((*ijk).asVec3d())
                        ? std::clamp(float(combine(xform.indexToWorld(*ijk), old)), -background, background)
                        : old;
                values[i][LeafT::coordToOffset(*ijk)] = value;
                changed[i] |= value != old;
            }
        }
    });
    writeLeafValues(origins, values, changed);
}

template <typename DisplacementFn>
void LocalPatch::advect(const Capsule& region, const DisplacementFn& displacement)
{
    const auto& xform = mField.grid().transform();
    remapActive(region, [&](const openvdb::Coord& ijk, const ConstAccessor& acc) {
        const openvdb::Vec3d world = xform.indexToWorld(ijk);
        return openvdb::tools::BoxSampler::sample(acc, xform.worldToIndex(world - displacement(world)));
    });
}

template <typename DistanceFn>
void LocalPatch::approach(const FalloffBall& ball, double fraction, double farthest, const DistanceFn& distance)
{
    const auto& xform = mField.grid().transform();
    const Capsule region = Capsule::ball(ball.centreWorld, ball.radiusWorld);
    const int n = substepsFor(fraction * farthest, mField.voxelSize());
    for (int i = 0; i < n; ++i) {
        // Step i takes the share of what is left that ends, after n steps, at 1 - fraction.
        const double before = 1.0 - fraction * i / n, after = 1.0 - fraction * (i + 1) / n;
        const double share = 1.0 - after / before;
        remapActive(region, [&](const openvdb::Coord& ijk, const ConstAccessor& acc) {
            const openvdb::Vec3d foot = closestSurfacePointAt(acc, ijk, xform);
            return acc.getValue(ijk) + share * ball.weightAt(foot) * distance(foot);
        });
        redistance();
    }
}

}  // namespace sculpt
