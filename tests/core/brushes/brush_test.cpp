// SPDX-License-Identifier: Apache-2.0
// Brushes (core/brushes/brush.h): each tool's effect against what it promises, on analytic shapes.

#include "core/base/errors.h"
#include "core/brushes/brush.h"
#include "core/field/csg_combine.h"
#include "core/field/grid_checksum.h"
#include "core/field/leaf_journal.h"
#include "core/mesh/field_measures.h"
#include "core/mesh/incremental_mesher.h"
#include "core/primitives/analytic_shapes.h"
#include "core/primitives/primitive_rasterizer.h"
#include "tests/support/mesh_checks.h"
#include "tests/support/surface_stats.h"

#include <gtest/gtest.h>
#include <openvdb/tools/Interpolation.h>

#include <cmath>
#include <random>
#include <set>

namespace sculpt {
namespace {

using openvdb::Vec3d;

BrushSettings brush(BrushTool tool, double radius, double strength = 1.0, Falloff falloff = Falloff::Smooth)
{
    BrushSettings b;
    b.tool = tool;
    b.radiusWorld = radius;
    b.strength = strength;
    b.falloff = falloff;
    return b;
}

BrushStamp stampAt(const Vec3d& centre, const Vec3d& previous)
{
    BrushStamp s;
    s.centreWorld = centre;
    s.previousWorld = previous;
    return s;
}
BrushStamp stampAt(const Vec3d& centre) { return stampAt(centre, centre); }

double volumeOf(const FieldImage& field) { return measureField(field).volume; }

/// Where phi crosses zero on the ray from `origin` along unit `direction` (first crossing from
/// inside to outside), by trilinear samples a tenth of a voxel apart.
double crossingAlong(const FieldImage& field, const Vec3d& origin, const Vec3d& direction, double maxDistance)
{
    const auto& xform = field.grid().transform();
    const auto acc = field.grid().getConstAccessor();
    const double step = 0.1 * field.voxelSize();
    double previous = openvdb::tools::BoxSampler::sample(acc, xform.worldToIndex(origin));
    for (double t = step; t <= maxDistance; t += step) {
        const double value = openvdb::tools::BoxSampler::sample(acc, xform.worldToIndex(origin + direction * t));
        if (previous < 0.0 && value >= 0.0) return t - step * value / (value - previous);
        previous = value;
    }
    return -1.0;
}

/// Volume of the lens where balls of radii R and r, centres d apart, overlap.
double lensVolume(double R, double r, double d)
{
    return M_PI * (R + r - d) * (R + r - d) * (d * d + 2 * d * r - 3 * r * r + 2 * d * R + 6 * r * R - 3 * R * R) /
           (12 * d);
}

/// Every voxel (active or not, of either grid's leaves) farther than `radius` from `centre` is
/// bit-identical in value and state.
void expectUntouchedBeyond(const FieldImage& before, const FieldImage& after, const Vec3d& centre, double radius)
{
    const auto& xform = before.grid().transform();
    const auto a = before.grid().getConstAccessor();
    const auto b = after.grid().getConstAccessor();
    std::size_t compared = 0, differing = 0;
    for (const FieldImage* grid : {&before, &after}) {
        for (auto leaf = grid->grid().tree().cbeginLeaf(); leaf; ++leaf) {
            for (auto it = leaf->cbeginValueAll(); it; ++it) {
                if ((xform.indexToWorld(it.getCoord()) - centre).length() <= radius) continue;
                ++compared;
                const openvdb::Coord ijk = it.getCoord();
                if (a.getValue(ijk) != b.getValue(ijk) || a.isValueOn(ijk) != b.isValueOn(ijk)) ++differing;
            }
        }
    }
    EXPECT_GT(compared, 1000u);
    EXPECT_EQ(differing, 0u);
}

/// Material that appeared (outside before, inside after) and disappeared, voxel by voxel.
struct MaterialChange {
    double added = 0.0, removed = 0.0;  ///< world volumes
    Vec3d addedCentroid{0.0}, removedCentroid{0.0};
};

MaterialChange materialChange(const FieldImage& before, const FieldImage& after)
{
    const auto& xform = before.grid().transform();
    const double cell = std::pow(before.voxelSize(), 3);
    const auto a = before.grid().getConstAccessor();
    const auto b = after.grid().getConstAccessor();
    std::set<openvdb::Coord> seen;
    MaterialChange change;
    for (const FieldImage* grid : {&before, &after}) {
        for (auto leaf = grid->grid().tree().cbeginLeaf(); leaf; ++leaf) {
            if (!seen.insert(leaf->origin()).second) continue;
            for (auto it = leaf->cbeginValueAll(); it; ++it) {
                const bool was = a.getValue(it.getCoord()) < 0.0f, is = b.getValue(it.getCoord()) < 0.0f;
                if (was == is) continue;
                const Vec3d p = xform.indexToWorld(it.getCoord());
                (is ? change.added : change.removed) += cell;
                (is ? change.addedCentroid : change.removedCentroid) += p * cell;
            }
        }
    }
    if (change.added > 0.0) change.addedCentroid /= change.added;
    if (change.removed > 0.0) change.removedCentroid /= change.removed;
    return change;
}

TEST(Brush, AddIsolatedStampAddsTheBallsVolume)
{
    FieldImage field = makeSphere(20.0, 1.0);
    const double before = volumeOf(field);
    applyStamp(field, brush(BrushTool::Add, 5.0, 1.0, Falloff::Constant), stampAt(Vec3d(40, 0, 0)), nullptr);
    const double ball = 4.0 / 3.0 * M_PI * 125.0;
    EXPECT_NEAR(volumeOf(field) - before, ball, 0.05 * ball);
    EXPECT_EQ(measureField(field).components, 2);
}

TEST(Brush, AddAndCarveOnTheSurfaceChangeVolumeByBallMinusLensAndLens)
{
    const double R = 20.0, r = 6.0, d = 20.0;
    const double lens = lensVolume(R, r, d), ball = 4.0 / 3.0 * M_PI * r * r * r;
    FieldImage added = makeSphere(R, 0.5);
    const double before = volumeOf(added);
    applyStamp(added, brush(BrushTool::Add, r, 1.0, Falloff::Constant), stampAt(Vec3d(d, 0, 0)), nullptr);
    EXPECT_NEAR(volumeOf(added) - before, ball - lens, 0.05 * (ball - lens));
    FieldImage carved = makeSphere(R, 0.5);
    applyStamp(carved, brush(BrushTool::Carve, r, 1.0, Falloff::Constant), stampAt(Vec3d(d, 0, 0)), nullptr);
    EXPECT_NEAR(before - volumeOf(carved), lens, 0.05 * lens);
}

TEST(Brush, AddSweepsACapsuleFromThePreviousStampSoFastStrokesLeaveNoBeads)
{
    FieldImage field = makeSphere(10.0, 0.5);
    const double before = volumeOf(field);
    const double r = 3.0, length = 16.0;
    applyStamp(field, brush(BrushTool::Add, r, 1.0, Falloff::Constant),
               stampAt(Vec3d(25, 0, length / 2), Vec3d(25, 0, -length / 2)), nullptr);
    const double capsule = M_PI * r * r * length + 4.0 / 3.0 * M_PI * r * r * r;
    EXPECT_NEAR(volumeOf(field) - before, capsule, 0.05 * capsule);
}

TEST(Brush, StrengthAndPressureScaleTheAddedBall)
{
    FieldImage field = makeSphere(10.0, 0.5);
    const double before = volumeOf(field);
    BrushStamp stamp = stampAt(Vec3d(25, 0, 0));
    stamp.pressure = 0.8;
    applyStamp(field, brush(BrushTool::Add, 5.0, 0.5, Falloff::Constant), stamp, nullptr);
    const double ball = 4.0 / 3.0 * M_PI * 8.0;  // radius 5 x 0.5 x 0.8 = 2
    EXPECT_NEAR(volumeOf(field) - before, ball, 0.05 * ball);
}

TEST(Brush, InflateAndDeflateMoveTheSurfaceAlongTheNormalAndNothingBeyondTheRadius)
{
    const double R = 30.0, r = 12.0;
    for (const double direction : {1.0, -1.0}) {
        const FieldImage original = makeSphere(R, 1.0);
        FieldImage field = makeSphere(R, 1.0);
        const Vec3d centre(R, 0, 0);
        applyStamp(field, brush(direction > 0 ? BrushTool::Inflate : BrushTool::Deflate, r), stampAt(centre), nullptr);
        // 0.1 r s p at the centre (falloff 1 there); half that where the smooth falloff is 0.5.
        EXPECT_NEAR(crossingAlong(field, Vec3d(0.0), Vec3d(1, 0, 0), 2 * R), R + direction * 0.1 * r, 0.15);
        const double angle = 2.0 * std::asin(0.5 * r / R / 2.0);  // surface point at chord r/2: q = 0.5
        const Vec3d dir(std::cos(angle), std::sin(angle), 0.0);
        EXPECT_NEAR(crossingAlong(field, Vec3d(0.0), dir, 2 * R), R + direction * 0.05 * r, 0.15);
        expectUntouchedBeyond(original, field, centre, r);
    }
}

TEST(Brush, SmoothLowersCurvatureVarianceUnderTheBrush)
{
    FieldImage field = makeSphere(20.0, 0.5);
    const Vec3d centre(20, 0, 0);
    for (const Vec3d& bump : {Vec3d(19.5, 3, 2), Vec3d(19.5, -3, 1), Vec3d(19.6, 0, -3.5), Vec3d(19.8, 1, 0)}) {
        applyStamp(field, brush(BrushTool::Add, 1.5, 1.0, Falloff::Constant), stampAt(bump), nullptr);
    }
    const auto under = std::make_pair(centre, 6.0);
    const double bumpy = test::curvatureVariance(field, under);
    for (int i = 0; i < 4; ++i) applyStamp(field, brush(BrushTool::Smooth, 8.0), stampAt(centre), nullptr);
    EXPECT_LT(test::curvatureVariance(field, under), 0.5 * bumpy);
}

TEST(Brush, SmoothWithKeepVolumeHoldsTheVolume)
{
    const double R = 10.0;
    const Vec3d centre(R, 0, 0);
    FieldImage plain = makeSphere(R, 0.5);
    FieldImage kept = makeSphere(R, 0.5);
    const double before = volumeOf(plain);
    BrushSettings keep = brush(BrushTool::Smooth, 9.0);
    keep.keepVolume = true;
    for (int i = 0; i < 12; ++i) {
        applyStamp(plain, brush(BrushTool::Smooth, 9.0), stampAt(centre), nullptr);
        applyStamp(kept, keep, stampAt(centre), nullptr);
    }
    EXPECT_LT(volumeOf(plain), before * (1.0 - 0.01)) << "smoothing alone shrinks it";
    EXPECT_NEAR(volumeOf(kept), before, 0.005 * before);
}

TEST(Brush, FlattenBringsTheSurfaceUnderTheBrushOntoTheFittedPlane)
{
    const double R = 30.0, r = 10.0, h = 1.0;
    FieldImage field = makeSphere(R, h);
    for (int i = 0; i < 3; ++i) {
        applyStamp(field, brush(BrushTool::Flatten, r, 1.0, Falloff::Constant), stampAt(Vec3d(R, 0, 0)), nullptr);
    }
    // The points under the inner half of the brush, and their least-squares plane x = mean
    // (the plane's normal is x by symmetry).
    const TriangleMesh mesh = meshLevelSet(field);
    std::vector<double> xs;
    for (const auto& p : mesh.positions) {
        if (p[0] > 0 && p[1] * p[1] + p[2] * p[2] < 0.25 * r * r) xs.push_back(p[0]);
    }
    ASSERT_GT(xs.size(), 50u);
    double mean = 0.0;
    for (double x : xs) mean += x / double(xs.size());
    for (double x : xs) EXPECT_NEAR(x, mean, 0.5 * h);
    EXPECT_LT(R - mean, 2.5);  // the plane cuts the cap near its base-to-top middle, not deeper
}

/// Mean |distance to `target`| of the mesh vertices of `field` within `radius` of `centre`.
double meanDistanceNear(const FieldImage& field, const FieldImage& target, const Vec3d& centre, double radius)
{
    const auto acc = target.grid().getConstAccessor();
    double sum = 0.0;
    int count = 0;
    for (const auto& p : meshLevelSet(field).positions) {
        const Vec3d q(p[0], p[1], p[2]);
        if ((q - centre).length() > radius) continue;
        sum += std::abs(openvdb::tools::BoxSampler::sample(acc, target.grid().transform().worldToIndex(q)));
        ++count;
    }
    EXPECT_GT(count, 20);
    return sum / std::max(count, 1);
}

TEST(Brush, FollowMovesTheSurfaceUnderTheBrushOntoTheTargetAndNothingBeyond)
{
    // A ball of radius 20 over a box of half side 17.5 (its own voxel size): the ball's cap
    // bulges 2.5 out of the box's +x face, beyond the box's band (1.5).
    const double R = 20.0, r = 7.0;
    const FieldImage original = makeSphere(R, 0.5);
    FieldImage field = makeSphere(R, 0.5);
    BrushSettings settings = brush(BrushTool::Follow, r);
    settings.target = std::make_shared<const FieldImage>(makeBox(17.5, 0.7));
    const Vec3d centre(R, 0, 0);
    const double before = meanDistanceNear(field, *settings.target, centre, 0.5 * r);
    for (int i = 0; i < 6; ++i) applyStamp(field, settings, stampAt(centre), nullptr);
    EXPECT_GT(before, 1.5);
    EXPECT_LT(meanDistanceNear(field, *settings.target, centre, 0.5 * r), 0.25);
    EXPECT_NEAR(crossingAlong(field, Vec3d(0.0), Vec3d(1, 0, 0), 2 * R), 17.5, 0.25);
    expectUntouchedBeyond(original, field, centre, r);
}

TEST(Brush, GrabMovesTheGrabbedMaterialAlongTheDrag)
{
    const double R = 20.0;
    const Vec3d start(R, 0, 0);
    // Pulled out: the point under the brush centre follows the pointer.
    FieldImage pulled = makeSphere(R, 0.5);
    applyStamp(pulled, brush(BrushTool::Grab, 8.0), stampAt(start + Vec3d(4, 0, 0), start), nullptr);
    EXPECT_NEAR(crossingAlong(pulled, Vec3d(0.0), Vec3d(1, 0, 0), 2 * R), R + 4.0, 0.5);
    // Dragged along the surface: material leaves the back of the brush and arrives in front.
    for (const Vec3d& drag : {Vec3d(0.0, 3.0, 0.0), Vec3d(0.0, -2.0, 2.0)}) {
        const FieldImage before = makeSphere(R, 0.5);
        FieldImage field = makeSphere(R, 0.5);
        applyStamp(field, brush(BrushTool::Grab, 8.0), stampAt(start + drag, start), nullptr);
        const MaterialChange change = materialChange(before, field);
        EXPECT_GT(change.added, 1.0);
        EXPECT_GT(change.removed, 1.0);
        const Vec3d moved = change.addedCentroid - change.removedCentroid;
        EXPECT_GT(moved.unit().dot(drag.unit()), 0.95) << drag << " moved material by " << moved;
    }
}

TEST(Brush, PinchNarrowsARidge)
{
    // A horizontal cylinder along x (radius 5) is the ridge; pinch along its top line.
    AnalyticSdf ridge;
    ridge.distance = [](const Vec3d& p) {
        const double along = std::clamp(p.x(), -20.0, 20.0);
        return (p - Vec3d(along, 0, 0)).length() - 5.0;
    };
    ridge.bounds = openvdb::BBoxd(Vec3d(-25, -5, -5), Vec3d(25, 5, 5));
    ridge.surfaceArea = 2 * M_PI * 5 * 40 + 4 * M_PI * 25;
    ridge.description = "ridge";
    FieldImage field = rasterizeSdf(ridge, 0.5);
    const auto width = [&] {  // across z at x = 0, at three quarters of the height
        const Vec3d at(0, 3.75, 0);
        return crossingAlong(field, at, Vec3d(0, 0, 1), 10) + crossingAlong(field, at, Vec3d(0, 0, -1), 10);
    };
    const double before = width();
    BrushStamp stamp = stampAt(Vec3d(2, 5, 0), Vec3d(-2, 5, 0));
    applyStamp(field, brush(BrushTool::Pinch, 6.0), stamp, nullptr);
    EXPECT_LT(width(), before - 0.5);
}

TEST(Brush, PrimitiveStampCombinesTheSetAtTheStamp)
{
    FieldImage field = makeSphere(10.0, 0.5);
    const double before = volumeOf(field);
    Primitive blob;
    blob.skeleton.type = SkeletonType::Point;
    blob.kernel.type = KernelType::SoftObject;
    blob.kernel.radius = 6.0;
    auto stamp =
        std::make_shared<PrimitiveStamp>(PrimitiveStamp{PrimitiveSet({blob}, 0.5, false), CsgOperation::Union});
    BrushSettings settings = brush(BrushTool::Primitive, 3.0);
    settings.primitive = stamp;
    applyStamp(field, settings, stampAt(Vec3d(30, 0, 0)), nullptr);
    const double added = volumeOf(field) - before;
    const double alone =
        volumeOf(rasterizePrimitives(stamp->primitives.translated(Vec3d(30, 0, 0)), field.grid().transform()));
    EXPECT_NEAR(added, alone, 0.02 * alone);
    EXPECT_EQ(measureField(field).components, 2);
}

TEST(Brush, AConstantCarveThroughATorusTubeLeavesOneShellAndNoDebris)
{
    // The carving ball's boundary grazes the tube's surface where the cut ends: before the speck
    // pass this left four one-voxel shells there (5 components, Euler characteristic 10).
    FieldImage torus = makeTorus(50.0, 50.0 / 3.0, 0.5);
    applyStamp(torus, brush(BrushTool::Carve, 20.0, 1.0, Falloff::Constant), stampAt(Vec3d(50, 0, 0)), nullptr);
    const FieldMeasures m = measureField(torus);
    EXPECT_EQ(m.components, 1);
    EXPECT_EQ(m.eulerCharacteristic, 2);  // the ring is cut: a ball's topology
}

/// Where a ray from far out along `direction` first meets the surface: where a sculptor's brush
/// lands (marching in quarter voxels, then interpolating).
Vec3d surfaceAlong(const FieldImage& field, const Vec3d& direction, double fromRadius)
{
    auto acc = field.grid().getConstAccessor();
    const auto phi = [&](double r) {
        return openvdb::tools::BoxSampler::sample(acc, field.grid().worldToIndex(direction * r));
    };
    const double step = 0.25 * field.voxelSize();
    double r = fromRadius;
    while (r > 0.0 && phi(r - step) > 0.0) r -= step;
    const double outside = phi(r), inside = phi(r - step);
    return direction * (r - step * outside / (outside - inside));
}

TEST(Brush, TwoHundredRandomAddAndCarveStampsWithHardFalloffsKeepOneShell)
{
    // Stamps land on the surface as it is (as a brush does), with constant and sharp falloffs:
    // the model stays one shell after every stroke, with no debris where balls graze it.
    FieldImage ball = makeSphere(20.0, 0.5);
    IncrementalMesher mesher;
    mesher.rebuild(ball);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), radius(1.5, 6.0);
    for (int i = 0; i < 200; ++i) {
        Vec3d direction(unit(rng), unit(rng), unit(rng));
        if (direction.length() < 1e-3) continue;
        direction.normalize();
        const BrushTool tool = i % 2 ? BrushTool::Carve : BrushTool::Add;
        const Falloff falloff = i % 4 < 2 ? Falloff::Constant : Falloff::Sharp;
        const Vec3d at = surfaceAlong(ball, direction, 40.0);
        mesher.update(ball, applyStamp(ball, brush(tool, radius(rng), 1.0, falloff), stampAt(at), nullptr));
        const std::vector<std::size_t> shells = test::shellTriangleCounts(mesher.weldedMesh());
        ASSERT_EQ(shells.size(), 1u) << "after stamp " << i << ": shells of " << shells.front() << " ... triangles";
    }
}

TEST(Brush, JournalRestoresTheGridBitForBitAndRedoes)
{
    Primitive blob;
    blob.skeleton.type = SkeletonType::Point;
    blob.kernel.type = KernelType::SoftObject;
    blob.kernel.radius = 6.0;
    const auto stamp =
        std::make_shared<PrimitiveStamp>(PrimitiveStamp{PrimitiveSet({blob}, 0.5, false), CsgOperation::Union});
    // The surface and the mask (what mask and unmask paint), as one state.
    const auto stateOf = [](const FieldImage& f) {
        return std::make_pair(gridChecksum(f.grid()), f.mask() ? gridChecksum(*f.mask()) : 0);
    };
    for (int t = 0; t < kBrushToolCount; ++t) {
        const BrushTool tool = BrushTool(t);
        FieldImage field = makeSphere(12.0, 0.5);
        if (tool == BrushTool::Unmask) {  // something to erase: the same path masked first
            for (int i = 0; i < 4; ++i)
                applyStamp(field, brush(BrushTool::Mask, 5.0, 1.0),
                           stampAt(Vec3d(12.0 * std::cos(0.3 * i), 12.0 * std::sin(0.3 * i), 0.0)), nullptr);
        }
        const FieldImage original = field.deepCopy();
        LeafJournal journal;
        for (int i = 0; i < 4; ++i) {
            const Vec3d at(12.0 * std::cos(0.3 * i), 12.0 * std::sin(0.3 * i), 0.0);
            const Vec3d previous(12.0 * std::cos(0.3 * (i - 1)), 12.0 * std::sin(0.3 * (i - 1)), 0.0);
            BrushSettings settings = brush(tool, 4.0, 0.7);
            settings.target = std::make_shared<const FieldImage>(makeBox(10.0, 0.5));
            settings.primitive = stamp;
            applyStamp(field, settings, stampAt(at, i ? previous : at), &journal);
        }
        const auto edited = stateOf(field);
        // A brush that did nothing would pass the rest: the stroke must have changed the grid or mask.
        ASSERT_NE(edited, stateOf(original)) << brushToolName(tool);
        journal.swap(field);
        EXPECT_EQ(stateOf(field), stateOf(original)) << brushToolName(tool);
        journal.swap(field);
        EXPECT_EQ(stateOf(field), edited) << brushToolName(tool);
    }
}

TEST(Brush, RejectsBadSettingsNamingTheField)
{
    FieldImage field = makeSphere(10.0, 0.5);
    const auto expectError = [&](const BrushSettings& b, const BrushStamp& s, const std::string& text) {
        try {
            applyStamp(field, b, s, nullptr);
            ADD_FAILURE() << "no error for " << text;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
        }
    };
    expectError(brush(BrushTool::Add, 0.0), stampAt(Vec3d(10, 0, 0)), "'radius'");
    expectError(brush(BrushTool::Add, -1.0), stampAt(Vec3d(10, 0, 0)), "'radius'");
    expectError(brush(BrushTool::Add, 2.0, 1.5), stampAt(Vec3d(10, 0, 0)), "'strength'");
    expectError(brush(BrushTool::Primitive, 2.0), stampAt(Vec3d(10, 0, 0)), "'primitives'");
    expectError(brush(BrushTool::Follow, 2.0), stampAt(Vec3d(10, 0, 0)), "'target'");
    expectError(brush(BrushTool::Add, 2.0), stampAt(Vec3d(std::nan(""), 0, 0)), "not finite");
    EXPECT_THROW(brushToolFromName("sponge"), InputError);
    EXPECT_THROW(falloffFromName("linear"), InputError);
}

}  // namespace
}  // namespace sculpt
