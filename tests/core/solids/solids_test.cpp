// SPDX-License-Identifier: Apache-2.0
// Hollowing and islands against analytic volumes and the marching-cubes mesh's topology.

#include "core/base/errors.h"
#include "core/field/central_difference.h"
#include "core/field/grid_checksum.h"
#include "core/field/leaf_journal.h"
#include "core/primitives/analytic_shapes.h"
#include "core/solids/hollow.h"
#include "core/solids/islands.h"
#include "core/solids/prism_cut.h"
#include "core/solids/wall_thickness.h"
#include "tests/support/solid_shapes.h"

#include <gtest/gtest.h>
#include <openvdb/tools/LevelSetMeasure.h>

#include <random>

namespace sculpt {
namespace {

using openvdb::Vec3d;
using test::ballsAndSpecks;
using test::frontSquare;
using test::plateWithFin;
using test::Topology;
using test::topologyOf;

double volumeOf(const FieldImage& field) { return openvdb::tools::levelSetVolume(field.grid()); }

TEST(Hollow, ABoxOfFortyWithAWallOfTwoHoldsTheShellsVolumeInTwoShells)
{
    const FieldImage box = makeBox(20.0, 0.5);
    HollowOptions options;
    options.thicknessWorld = 2.0;
    const HollowResult shell = hollow(box, options);
    EXPECT_NEAR(volumeOf(shell.field), 40.0 * 40.0 * 40.0 - 36.0 * 36.0 * 36.0, 0.01 * (64000.0 - 46656.0));
    const Topology t = topologyOf(shell.field);
    EXPECT_TRUE(t.closedManifold);
    EXPECT_EQ(t.shells, 2u);
    EXPECT_EQ(t.euler, 4);
    ASSERT_EQ(shell.cavityBottoms.size(), 1u);
    EXPECT_NEAR(shell.cavityBottoms.front().z(), -18.0, 0.5);
    // The outer wall keeps its voxels: the box's band is far from the cavity (2 mm = 4 voxels, band 3).
    const auto was = box.grid().getConstAccessor();
    std::size_t outerChanged = 0;
    for (auto it = shell.field.grid().cbeginValueOn(); it; ++it)
        outerChanged += *it > -1.0f && was.getValue(it.getCoord()) != *it && was.isValueOn(it.getCoord());
    EXPECT_EQ(outerChanged, 0u);
}

TEST(Hollow, ADrainHoleJoinsTheCavityToTheOutside)
{
    FieldImage box = makeBox(20.0, 0.5);
    HollowOptions options;
    options.thicknessWorld = 2.0;
    HollowResult shell = hollow(box, options);
    const double closed = volumeOf(shell.field);
    cutDrainHoles(shell.field, drainHolesUnder(shell.cavityBottoms, {0, 0, 1}, options.thicknessWorld, 1.5));
    const Topology t = topologyOf(shell.field);
    EXPECT_TRUE(t.closedManifold);
    EXPECT_EQ(t.shells, 1u);
    EXPECT_EQ(t.euler, 2);
    // The hole takes about a cylinder of radius 1.5 through the wall of 2.
    EXPECT_NEAR(closed - volumeOf(shell.field), M_PI * 1.5 * 1.5 * 2.0, 0.35 * M_PI * 1.5 * 1.5 * 2.0);
}

TEST(Hollow, AHoleDrilledWhereClickedJoinsTheCavityAndUndoesBitForBit)
{
    const FieldImage ball = makeSphere(10.0, 0.5);
    HollowOptions options;
    options.thicknessWorld = 2.0;
    FieldImage shell = hollow(ball, options).field;
    ASSERT_EQ(topologyOf(shell).shells, 2u);
    // Clicked on the side (x = 10, outward normal +x): straight in through the wall of 2.
    const std::optional<DrainHole> hole = drainHoleAt(shell, Vec3d(10, 0, 0), Vec3d(1, 0, 0), 1.0, 20.0);
    ASSERT_TRUE(hole.has_value());
    EXPECT_NEAR(hole->from.x(), 11.0, 1e-9);
    EXPECT_NEAR(hole->to.x(), 10.0 - 2.0 - 1.0, 0.5);
    const std::uint64_t before = gridChecksum(shell.grid());
    LeafJournal journal;
    cutDrainHoles(shell, {*hole}, &journal);
    const Topology t = topologyOf(shell);
    EXPECT_TRUE(t.closedManifold);
    EXPECT_EQ(t.shells, 1u);
    EXPECT_EQ(t.euler, 2);
    journal.swap(shell);
    EXPECT_EQ(gridChecksum(shell.grid()), before);
    // A solid ball has no cavity behind its wall: nothing to drain.
    EXPECT_FALSE(drainHoleAt(ball, Vec3d(10, 0, 0), Vec3d(1, 0, 0), 1.0, 5.0).has_value());
    EXPECT_THROW(cutDrainHoles(shell, {{Vec3d(0.0), Vec3d(1.0), -1.0}}), InputError);
}

TEST(Hollow, WallsThinnerThanAVoxelStillMeshClosedAndMedialAndOutsideShellsHoldTheirVolumes)
{
    const double h = 0.5;
    const FieldImage ball = makeSphere(10.0, h);
    HollowOptions thin;
    thin.thicknessWorld = 0.7 * h;
    EXPECT_TRUE(topologyOf(hollow(ball, thin).field).closedManifold);

    const auto shellVolume = [](double inner, double outer) {
        return 4.0 / 3.0 * M_PI * (std::pow(outer, 3) - std::pow(inner, 3));
    };
    HollowOptions medial;
    medial.thicknessWorld = 2.0;
    medial.side = ShellSide::Medial;
    EXPECT_NEAR(volumeOf(hollow(ball, medial).field), shellVolume(9.0, 11.0), 0.02 * shellVolume(9.0, 11.0));
    HollowOptions outside = medial;
    outside.side = ShellSide::Outside;
    EXPECT_NEAR(volumeOf(hollow(ball, outside).field), shellVolume(10.0, 12.0), 0.02 * shellVolume(10.0, 12.0));
    HollowOptions closed = medial;
    closed.side = ShellSide::Inside;
    closed.closingWorld = 1.0;  // a ball's cavity has no narrow part: the closing changes nothing much
    EXPECT_NEAR(volumeOf(hollow(ball, closed).field), shellVolume(8.0, 10.0), 0.02 * shellVolume(8.0, 10.0));
}

TEST(Islands, RemovingThoseUnderACubicMillimetreLeavesTheTwoBallsBitForBit)
{
    FieldImage field = ballsAndSpecks();
    const FieldImage before = field.deepCopy();
    ASSERT_EQ(topologyOf(field).shells, 22u);
    EXPECT_EQ(removeIslandsUnder(field, 1.0), 20u);
    EXPECT_EQ(topologyOf(field).shells, 2u);
    const auto was = before.grid().getConstAccessor();
    std::size_t ballChanged = 0;
    for (auto it = field.grid().cbeginValueOn(); it; ++it) ballChanged += was.getValue(it.getCoord()) != *it;
    EXPECT_EQ(ballChanged, 0u);
    // Nothing of the specks is left, not even their band.
    const auto now = field.grid().getConstAccessor();
    std::size_t ballVoxels = 0;
    for (auto it = before.grid().cbeginValueOn(); it; ++it)
        ballVoxels += std::abs(it.getCoord().x() * 0.2) <= 13.8 && std::abs(it.getCoord().y() * 0.2) <= 5.8 &&
                      std::abs(it.getCoord().z() * 0.2) <= 5.8 && now.isValueOn(it.getCoord());
    EXPECT_EQ(field.grid().activeVoxelCount(), ballVoxels);
    EXPECT_NEAR(volumeOf(field), 2 * 4.0 / 3.0 * M_PI * 125.0, 0.01 * 2 * 4.0 / 3.0 * M_PI * 125.0);
}

TEST(Islands, KeepingTheOneUnderAPointAndItsComplementUniteIntoTheInput)
{
    const FieldImage field = ballsAndSpecks();
    const std::vector<Island> islands = findIslands(field);
    ASSERT_EQ(islands.size(), 22u);
    const int left = islandAt(islands, Vec3d(-13.0, 0.0, 0.0), 0.5);  // on the left ball's surface
    ASSERT_GE(left, 0);
    EXPECT_NEAR(islands[std::size_t(left)].bounds.min().x(), -13.6, 0.3);  // its band reaches 3 voxels out
    FieldImage kept = field.deepCopy(), rest = field.deepCopy();
    keepOrRemoveIsland(kept, islands, std::size_t(left), true);
    keepOrRemoveIsland(rest, islands, std::size_t(left), false);
    EXPECT_EQ(topologyOf(kept).shells, 1u);
    EXPECT_EQ(topologyOf(rest).shells, 21u);
    // Their union (the minimum) is the input on every active voxel.
    const auto a = kept.grid().getConstAccessor(), b = rest.grid().getConstAccessor();
    std::size_t differ = 0;
    for (auto it = field.grid().cbeginValueOn(); it; ++it)
        differ += std::min(a.getValue(it.getCoord()), b.getValue(it.getCoord())) != *it;
    EXPECT_EQ(differ, 0u);
}

/// The ball of radius r less the column x > a, y > b (along z), by the midpoint rule.
double ballLessCorner(double r, double a, double b)
{
    const int n = 2000;
    const double step = r / n;
    double removed = 0.0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double x = (i + 0.5) * step, y = (j + 0.5) * step;
            if (x > a && y > b && x * x + y * y < r * r)
                removed += 2.0 * std::sqrt(r * r - x * x - y * y) * step * step;
        }
    return 4.0 / 3.0 * M_PI * r * r * r - removed;
}

TEST(PrismCut, AFrontSquareCutThroughABallRemovesItsPrism)
{
    const FieldImage ball = makeSphere(25.0, 0.5);
    const FieldImage cut = applyPrism(ball, frontSquare(8.0, 6.0, 60.0, 60.0), PrismMode::Cut);
    const double expected = ballLessCorner(25.0, 8.0, 6.0);
    EXPECT_NEAR(volumeOf(cut), expected, 0.005 * expected);
    const Topology t = topologyOf(cut);
    EXPECT_TRUE(t.closedManifold);
    EXPECT_EQ(t.shells, 1u);
    EXPECT_EQ(t.euler, 2);
    // Away from the prism the ball keeps its voxels.
    const auto was = ball.grid().getConstAccessor();
    std::size_t changedFar = 0;
    for (auto it = cut.grid().cbeginValueOn(); it; ++it) {
        const Vec3d p = cut.grid().transform().indexToWorld(it.getCoord());
        changedFar += (p.x() < 5.0 || p.y() < 3.0) && was.getValue(it.getCoord()) != *it;
    }
    EXPECT_EQ(changedFar, 0u);
}

TEST(PrismCut, MirroredAcrossXTheCutFieldIsMirrorSymmetric)
{
    ViewPrism prism = frontSquare(8.0, 6.0, 60.0, 60.0);
    prism.mirror = {true, false, false};
    const FieldImage cut = applyPrism(makeSphere(25.0, 0.5), prism, PrismMode::Cut);
    const auto acc = cut.grid().getConstAccessor();
    std::size_t asymmetric = 0, visited = 0;
    for (auto it = cut.grid().cbeginValueOn(); it; ++it, ++visited) {
        const openvdb::Coord m(-it.getCoord().x(), it.getCoord().y(), it.getCoord().z());
        asymmetric += acc.getValue(m) != *it || !acc.isValueOn(m);
    }
    EXPECT_GT(visited, 10000u);
    EXPECT_EQ(asymmetric, 0u);
    const double expected = ballLessCorner(25.0, 8.0, 6.0) * 2.0 - 4.0 / 3.0 * M_PI * 25.0 * 25.0 * 25.0;
    EXPECT_NEAR(volumeOf(cut), expected, 0.005 * expected);
}

// A lasso at the limit the README states: 100,000 points drawn round a circle of radius a (with a
// hand's wobble far under a voxel) bores a hole of radius a through the ball, leaving
// (4 pi / 3) (R^2 - a^2)^(3/2). Its time (about 0.1 s) is in masks_bench, not asserted here.
TEST(PrismCut, AHundredThousandPointLassoBoresTheHoleItsCircleDraws)
{
    const double radius = 20.0, a = 8.0;
    ViewPrism prism = frontSquare(0.0, 0.0, 1.0, 1.0);
    prism.polygon.clear();
    for (int i = 0; i < 100000; ++i) {
        const double t = 2.0 * M_PI * i / 100000.0, wobble = 0.01 * std::sin(997.0 * t);
        prism.polygon.emplace_back((a + wobble) * std::cos(t), (a + wobble) * std::sin(t));
    }
    const FieldImage cut = applyPrism(makeSphere(radius, 0.5), prism, PrismMode::Cut);
    const double expected = 4.0 / 3.0 * M_PI * std::pow(radius * radius - a * a, 1.5);
    EXPECT_NEAR(volumeOf(cut), expected, 0.01 * expected);
    const Topology t = topologyOf(cut);
    EXPECT_TRUE(t.closedManifold);
    EXPECT_EQ(t.shells, 1u);
    EXPECT_EQ(t.euler, 0) << "a ring: the hole goes through";
}

TEST(PrismCut, AFillSlabAddsItsBoxAndAPerspectivePyramidCutsWhatTheEyeSees)
{
    const FieldImage ball = makeSphere(10.0, 0.5);
    ViewPrism slab = frontSquare(-4.0, -4.0, 4.0, 4.0);
    slab.nearDepth = 80.0;  // z from 20 down to 5: a 8 x 8 x 15 box, 5 of it inside the ball
    slab.farDepth = 95.0;
    const FieldImage filled = applyPrism(ball, slab, PrismMode::Fill);
    EXPECT_GT(volumeOf(filled), volumeOf(ball) + 8.0 * 8.0 * 9.0);
    EXPECT_LT(volumeOf(filled), volumeOf(ball) + 8.0 * 8.0 * 15.0);
    EXPECT_EQ(topologyOf(filled).shells, 1u);

    // From the eye at z = 100, the rays through (+-0.05, +-0.05) span +-5 at the ball's centre.
    ViewPrism pyramid = frontSquare(-0.05, -0.05, 0.05, 0.05);
    pyramid.perspective = true;
    const FieldImage holed = applyPrism(ball, pyramid, PrismMode::Cut);
    const Topology t = topologyOf(holed);
    EXPECT_EQ(t.shells, 1u);
    EXPECT_EQ(t.euler, 0) << "a square hole through the ball: a torus";
    const double removed = volumeOf(ball) - volumeOf(holed);
    EXPECT_GT(removed, 0.8 * 10.0 * 10.0 * 16.0);
    EXPECT_LT(removed, 10.0 * 10.0 * 20.0);
    EXPECT_THROW(applyPrism(ball, frontSquare(-1, -1, 1, 1), PrismMode::Fill), InputError) << "a fill needs a depth";
}

/// The binned distance against every edge's, at `samples` random points: equal under the cap,
/// the same sign beyond, for the prism seen in parallel and in perspective.
void expectBinnedAsExact(const ViewPrism& prism, int samples)
{
    std::mt19937 random(3);
    std::uniform_real_distribution<double> coordinate(-20.0, 20.0);
    const openvdb::BBoxd box(Vec3d(-20.0), Vec3d(20.0));
    for (const bool perspective : {false, true}) {
        ViewPrism seen = prism;
        seen.perspective = perspective;
        if (perspective)
            for (openvdb::Vec2d& p : seen.polygon) p *= 1.0 / 100.0;  // tangents at depth 100
        const double cap = 1.5;
        const PrismDistance binned(seen, cap, box);
        std::size_t near = 0;
        for (int i = 0; i < samples; ++i) {
            const Vec3d p(coordinate(random), coordinate(random), coordinate(random));
            const double exact = seen.distance(p), fast = binned(p);
            if (std::abs(exact) < cap) {
                EXPECT_EQ(fast, exact) << p;
                ++near;
            } else {
                EXPECT_GE(std::abs(fast), cap - 1e-12) << p;
                EXPECT_EQ(fast < 0.0, exact < 0.0) << p;
            }
        }
        EXPECT_GT(near, std::size_t(samples / 20));
    }
}

TEST(PrismCut, TheBinnedDistanceIsEveryEdgesUnderItsCapAndHasItsSignBeyond)
{
    // A star-shaped lasso crossing itself (a pentagram: even-odd leaves its centre outside),
    // mirrored across x.
    ViewPrism prism = frontSquare(0, 0, 1, 1);
    prism.polygon.clear();
    for (int i = 0; i < 5; ++i) {
        const double a = 2.0 * M_PI * (2 * i) / 5.0;
        prism.polygon.emplace_back(3.0 + 12.0 * std::cos(a), 12.0 * std::sin(a));
    }
    prism.mirror = {true, false, false};
    expectBinnedAsExact(prism, 20000);
    // A long careful lasso: 12,000 points on a rose that crosses itself many times, thousands of
    // edges to a row of the bins (each point is answered from its cell's centre).
    prism.polygon.clear();
    for (int i = 0; i < 12000; ++i) {
        const double a = 2.0 * M_PI * i / 12000.0, r = 6.0 + 8.0 * std::cos(7.0 * a);
        prism.polygon.emplace_back(r * std::cos(a), r * std::sin(a));
    }
    expectBinnedAsExact(prism, 4000);
}

TEST(WallThickness, APlateReadsItsThicknessAndOnlyItsThinFinIsFlagged)
{
    const double h = 0.1;
    const FieldImage plate = plateWithFin(h);
    const auto plateT = wallThicknessAt(plate.grid(), Vec3d(5, 3, 1), Vec3d(0, 0, 1), 10.0);
    ASSERT_TRUE(plateT.has_value());
    EXPECT_NEAR(*plateT, 2.0, h);
    const auto finT = wallThicknessAt(plate.grid(), Vec3d(0.3, 0, 3), Vec3d(1, 0, 0), 10.0);
    ASSERT_TRUE(finT.has_value());
    EXPECT_NEAR(*finT, 0.6, h);
    EXPECT_FALSE(wallThicknessAt(plate.grid(), Vec3d(5, 3, 1), Vec3d(0, 0, 1), 1.0).has_value());

    const std::optional<ThinnestWall> thinnest = thinnestWall(plate, 1.0);
    ASSERT_TRUE(thinnest.has_value());
    EXPECT_NEAR(thinnest->thickness, 0.6, h);
    EXPECT_LE(std::abs(thinnest->where.x()), 0.3 + 2 * h);
    EXPECT_GE(thinnest->where.z(), 1.0 - 2 * h);
    // Every surface point under 1 mm is on the fin.
    const auto acc = plate.grid().getConstAccessor();
    std::size_t flagged = 0, offFin = 0;
    for (auto it = plate.grid().cbeginValueOn(); it; ++it) {
        if (std::abs(*it) > 0.5 * h) continue;
        const Vec3d difference = centralDifferenceAt(acc, it.getCoord());
        const Vec3d foot = closestSurfacePoint(plate.grid().transform().indexToWorld(it.getCoord()), *it, difference);
        const auto t = wallThicknessAt(plate.grid(), foot, difference.unitSafe(), 1.0);
        if (!t) continue;
        ++flagged;
        offFin += std::abs(foot.x()) > 0.3 + 2 * h || foot.z() < 1.0 - 2 * h;
    }
    EXPECT_GT(flagged, 100u);
    EXPECT_EQ(offFin, 0u);
}

TEST(WallThickness, AFortyFiveDegreeChamferOverhangsFortyFiveDegrees)
{
    const double h = 0.1;
    const FieldImage plate = plateWithFin(h);
    const auto acc = plate.grid().getConstAccessor();
    std::size_t measured = 0;
    for (auto it = plate.grid().cbeginValueOn(); it; ++it) {
        const Vec3d p = plate.grid().transform().indexToWorld(it.getCoord());
        // On the chamfer (the plane y + z = -10, z from -1 to 0), away from its edges.
        if (std::abs(*it) > 0.5 * h || std::abs(p.x()) > 8.0 || p.z() > -0.2 || p.z() < -0.8 || p.y() > -8.5) continue;
        const Vec3d normal = centralDifferenceAt(acc, it.getCoord()).unitSafe();
        const auto overhang = overhangDegrees(normal, Vec3d(0, 0, 1));
        ASSERT_TRUE(overhang.has_value()) << p;
        EXPECT_NEAR(*overhang, 45.0, 2.0) << p;
        ++measured;
    }
    EXPECT_GT(measured, 100u);
    EXPECT_FALSE(overhangDegrees(Vec3d(0, 0, 1), Vec3d(0, 0, 1)).has_value()) << "a face looking up";
    EXPECT_NEAR(*overhangDegrees(Vec3d(0, 0, -1), Vec3d(0, 0, 1)), 0.0, 1e-9) << "facing the plate";
}

}  // namespace
}  // namespace sculpt
