// SPDX-License-Identifier: Apache-2.0
// Local band redistancing against OpenVDB's LevelSetTracker run on the same patch: after the
// surface moved by part of a voxel, both rebuild the band, ours only inside its zone.

#include "core/field/band_rule.h"
#include "core/local/band_redistance.h"
#include "core/primitives/analytic_shapes.h"

#include <gtest/gtest.h>
#include <openvdb/tools/LevelSetTracker.h>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace sculpt {
namespace {

constexpr double kRadius = 12.0, kVoxel = 0.5;

/// A sphere's band moved outwards by `shiftVoxels` without rebuilding it, as one sub-step of a
/// brush leaves it: the values are exact distances to the moved sphere, stored by the band rule,
/// but the band's outer edge lags (voxels there still hold +background).
openvdb::FloatGrid::Ptr movedSphere(double shiftVoxels)
{
    openvdb::FloatGrid::Ptr grid = makeSphere(kRadius, kVoxel).gridPtr()->deepCopy();
    const float background = grid->background();
    for (auto leaf = grid->tree().beginLeaf(); leaf; ++leaf) {
        for (auto it = leaf->beginValueOn(); it; ++it) {
            const BandValue band = toBand(float(*it - shiftVoxels * kVoxel), background);
            it.setValue(band.value);
            it.setValueOn(band.active);
        }
    }
    return grid;
}

openvdb::FloatGrid::Ptr trackedByOpenVdb(const openvdb::FloatGrid& grid)
{
    openvdb::FloatGrid::Ptr copy = grid.deepCopy();
    openvdb::tools::LevelSetTracker<openvdb::FloatGrid> tracker(*copy);
    tracker.setSpatialScheme(openvdb::math::FIRST_BIAS);  // the scheme ours uses
    tracker.setTemporalScheme(openvdb::math::TVD_RK1);
    tracker.setNormCount(1);
    tracker.track();
    return copy;
}

TEST(BandRedistance, AgreesWithLevelSetTrackerInsideItsZoneAndKeepsTheRestBitForBit)
{
    const double shiftVoxels = 0.6;
    const openvdb::FloatGrid::Ptr moved = movedSphere(shiftVoxels);
    const openvdb::FloatGrid::Ptr reference = trackedByOpenVdb(*moved);
    openvdb::FloatGrid::Ptr ours = moved->deepCopy();
    const openvdb::Vec3d centre(kRadius, 0.0, 0.0);
    const Capsule zone = Capsule::ball(centre, 4.0);
    redistanceBand(*ours, zone);

    const double exactRadius = kRadius + shiftVoxels * kVoxel;
    const float background = ours->background();
    const auto& xform = ours->transform();
    const auto movedAcc = moved->getConstAccessor();
    const auto referenceAcc = reference->getConstAccessor();
    const auto oursAcc = ours->getConstAccessor();
    double worstDifference = 0.0, worstOurs = 0.0, worstTracker = 0.0;
    int compared = 0, outsideChecked = 0;
    const openvdb::CoordBBox box(xform.worldToIndexCellCentered(openvdb::Vec3d(-kRadius - 3.0)),
                                 xform.worldToIndexCellCentered(openvdb::Vec3d(kRadius + 3.0)));
    for (auto ijk = box.begin(); ijk; ++ijk) {
        const openvdb::Vec3d world = xform.indexToWorld(*ijk);
        const float value = oursAcc.getValue(*ijk);
        if (!zone.contains(world)) {
            if (std::abs(movedAcc.getValue(*ijk)) < background) ++outsideChecked;
            ASSERT_EQ(value, movedAcc.getValue(*ijk)) << *ijk;
            ASSERT_EQ(oursAcc.isValueOn(*ijk), movedAcc.isValueOn(*ijk)) << *ijk;
            continue;
        }
        // The band rule holds: active exactly where the value is a distance inside the band.
        ASSERT_EQ(oursAcc.isValueOn(*ijk), toBand(value, background).active) << *ijk;
        const double exact = world.length() - exactRadius;
        if (std::abs(exact) > 2.0 * kVoxel) continue;  // the band's core, where both must be right
        ++compared;
        worstDifference = std::max(worstDifference, double(std::abs(value - referenceAcc.getValue(*ijk))));
        worstOurs = std::max(worstOurs, std::abs(value - exact));
        worstTracker = std::max(worstTracker, std::abs(referenceAcc.getValue(*ijk) - exact));
    }
    ASSERT_GT(compared, 500);
    ASSERT_GT(outsideChecked, 10000);
    std::cout << "worst |ours - tracker| " << worstDifference / kVoxel << ", |ours - exact| " << worstOurs / kVoxel
              << ", |tracker - exact| " << worstTracker / kVoxel << " voxel over " << compared << " voxels\n";
    EXPECT_LT(worstDifference, 0.01 * kVoxel);
    EXPECT_LT(worstOurs, worstTracker + 0.02 * kVoxel) << "tracker's worst error " << worstTracker / kVoxel << " voxel";
    EXPECT_LT(worstOurs, 0.02 * kVoxel);
}

TEST(BandRedistance, RebuildsTheLaggingOuterEdgeOfTheBand)
{
    // After moving out by 0.6 voxel, voxels 2.4 .. 3 voxels outside the moved surface hold no
    // distance yet (they were beyond the old band); the tracker and ours both fill them.
    const openvdb::FloatGrid::Ptr moved = movedSphere(0.6);
    openvdb::FloatGrid::Ptr ours = moved->deepCopy();
    redistanceBand(*ours, Capsule::ball(openvdb::Vec3d(0.0), 2.0 * kRadius));
    const openvdb::FloatGrid::Ptr reference = trackedByOpenVdb(*moved);
    EXPECT_GT(ours->activeVoxelCount(), moved->activeVoxelCount());
    const double ratio = double(ours->activeVoxelCount()) / double(reference->activeVoxelCount());
    EXPECT_NEAR(ratio, 1.0, 0.03) << ours->activeVoxelCount() << " active voxels, tracker "
                                  << reference->activeVoxelCount();
}

}  // namespace
}  // namespace sculpt
