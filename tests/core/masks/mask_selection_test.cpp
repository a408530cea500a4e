// SPDX-License-Identifier: Apache-2.0
// Mask selections mask exactly what they select, judged by each voxel's closest surface point on
// shapes whose answer is known: a square seen from the front, the inner wall of a hollow ball, a
// thin fin on a thick plate, one ball among specks.

#include "core/base/errors.h"
#include "core/field/central_difference.h"
#include "core/field/grid_checksum.h"
#include "core/field/leaf_journal.h"
#include "core/field/surface_mask.h"
#include "core/masks/mask_selection.h"
#include "core/primitives/analytic_shapes.h"
#include "core/solids/hollow.h"
#include "tests/support/solid_shapes.h"

#include <gtest/gtest.h>

#include <functional>

namespace sculpt {
namespace {

using openvdb::Vec3d;

/// Voxels of the band within half a voxel of the surface, by what `classify` says of their
/// closest surface point: of the selected ones, how many are masked (>= 0.99) and how many not;
/// of the others, how many are free (0) and how many masked at all.
struct Tally {
    std::size_t selectedMasked = 0, selectedFree = 0, otherFree = 0, otherMasked = 0;
};

Tally tally(const FieldImage& field, const std::function<int(const Vec3d& foot)>& classify)
{
    Tally t;
    const openvdb::FloatGrid::Ptr none = makeMaskGrid(field.grid().transform());
    const MaskReader reader(field.mask() ? *field.mask() : *none);
    const auto acc = field.grid().getConstAccessor();
    const double h = field.voxelSize();
    for (auto it = field.grid().cbeginValueOn(); it; ++it) {
        if (std::abs(*it) > 0.5 * h) continue;
        const Vec3d foot = closestSurfacePoint(field.grid().transform().indexToWorld(it.getCoord()), *it,
                                               centralDifferenceAt(acc, it.getCoord()));
        const int kind = classify(foot);  // 1 selected, 0 not, -1 at the edge (not counted)
        const double m = reader.at(it.getCoord());
        if (kind == 1) (m >= 0.99 ? t.selectedMasked : t.selectedFree)++;
        if (kind == 0) (m == 0.0 ? t.otherFree : t.otherMasked)++;
    }
    return t;
}

std::uint64_t maskChecksum(const FieldImage& field) { return field.mask() ? gridChecksum(*field.mask()) : 0; }

TEST(MaskSelection, ABoxSeenFromTheFrontMasksTheClayInItThroughAndErasingFreesItAgain)
{
    FieldImage ball = makeSphere(8.0, 0.5);
    MaskSelection box;
    box.prism = test::frontSquare(2.0, -1.0, 20.0, 20.0);  // x > 2, y > -1, through the ball along z
    LeafJournal journal;
    applyMaskSelection(ball, box, &journal);
    const auto inBox = [](const Vec3d& p) {
        if (p.x() > 2.6 && p.y() > -0.4) return 1;
        return p.x() < 1.4 || p.y() < -1.6 ? 0 : -1;
    };
    const Tally t = tally(ball, inBox);
    EXPECT_GT(t.selectedMasked, 500u);
    EXPECT_EQ(t.selectedFree, 0u) << "front and back alike: the box masks through";
    EXPECT_GT(t.otherFree, 1000u);
    EXPECT_EQ(t.otherMasked, 0u);

    const std::uint64_t masked = maskChecksum(ball);
    box.erase = true;
    applyMaskSelection(ball, box, &journal);
    EXPECT_EQ(ball.mask()->activeVoxelCount(), 0u);
    journal.swap(ball);  // undoes both selections at once
    EXPECT_EQ(maskChecksum(ball), 0u);
    EXPECT_NE(masked, 0u);
    EXPECT_THROW(applyMaskSelection(ball, MaskSelection{}, nullptr), InputError) << "no polygon";
}

TEST(MaskSelection, CavitiesAreTheInnerWallOfAHollowBallAndNotItsOuterWall)
{
    HollowOptions options;
    options.thicknessWorld = 4.0;  // 8 voxels: each wall's curvature is read off its own side
    FieldImage shell = hollow(makeSphere(10.0, 0.5), options).field;  // walls at r = 10 and r = 6
    MaskSelection cavity;
    cavity.kind = MaskSelectionKind::Cavity;
    cavity.creaseRadiusWorld = 10.0;  // s = r / 6 on the inner wall: fully masked
    applyMaskSelection(shell, cavity, nullptr);
    const Tally t = tally(shell, [](const Vec3d& p) { return p.length() < 8.0 ? 1 : 0; });
    EXPECT_GT(t.selectedMasked, 1000u);
    EXPECT_EQ(t.selectedFree, 0u);
    EXPECT_GT(t.otherFree, 1000u);
    EXPECT_EQ(t.otherMasked, 0u) << "the outer wall curves outwards";
    cavity.creaseRadiusWorld = -1.0;
    EXPECT_THROW(applyMaskSelection(shell, cavity, nullptr), InputError);
}

TEST(MaskSelection, ThinWallsAreTheFinAndNotThePlate)
{
    const double h = 0.1;
    FieldImage plate = test::plateWithFin(h);
    MaskSelection thin;
    thin.kind = MaskSelectionKind::Thin;
    thin.thicknessWorld = 1.0;
    applyMaskSelection(plate, thin, nullptr);
    // The fin's two sides (0.6 thick) above the plate's fillet; the plate's faces (2 thick) away from the fin.
    const Tally t = tally(plate, [h](const Vec3d& p) {
        if (std::abs(std::abs(p.x()) - 0.3) < h && p.z() > 1.5 && p.z() < 4.5 && std::abs(p.y()) < 7.5) return 1;
        return std::abs(p.x()) > 1.5 && std::abs(p.y()) < 9.0 && std::abs(p.x()) < 9.0 ? 0 : -1;
    });
    EXPECT_GT(t.selectedMasked, 1000u);
    EXPECT_EQ(t.selectedFree, 0u);
    EXPECT_GT(t.otherFree, 10000u);
    EXPECT_EQ(t.otherMasked, 0u);
}

TEST(MaskSelection, AnIslandIsMaskedWholeAndNothingElse)
{
    FieldImage field = test::ballsAndSpecks();
    MaskSelection island;
    island.kind = MaskSelectionKind::Island;
    island.point = Vec3d(-13.0, 0.0, 0.0);  // on the left ball
    applyMaskSelection(field, island, nullptr);
    const Tally t = tally(field, [](const Vec3d& p) { return (p - Vec3d(-8, 0, 0)).length() < 5.5 ? 1 : 0; });
    EXPECT_GT(t.selectedMasked, 1000u);
    EXPECT_EQ(t.selectedFree, 0u);
    EXPECT_GT(t.otherFree, 1000u);
    EXPECT_EQ(t.otherMasked, 0u) << "the right ball and the specks stay free";
    island.point = Vec3d(100.0, 0.0, 0.0);
    EXPECT_THROW(applyMaskSelection(field, island, nullptr), InputError) << "no island there";
}

}  // namespace
}  // namespace sculpt
