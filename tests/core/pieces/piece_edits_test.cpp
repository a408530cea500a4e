// SPDX-License-Identifier: Apache-2.0
#include "core/field/grid_checksum.h"
#include "core/mesh/field_measures.h"
#include "core/pieces/piece_edits.h"
#include "core/primitives/analytic_shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace sculpt {
namespace {

constexpr double kPi = 3.14159265358979323846;

Piece sphereAt(const std::string& name, double radius, double voxelSize, const openvdb::Vec3d& centre)
{
    Piece piece{{name}, makeSphere(radius, voxelSize)};
    piece.placement.setTranslation(centre);
    return piece;
}

}  // namespace

// Two balls of radius 5, 6 apart, placed (not resampled) and on lattices of different voxel sizes,
// merge into their union: twice a ball less the lens they share, pi (4r + d) (2r - d)^2 / 12.
TEST(PieceEdits, MergeUnitesTwoPlacedPiecesOnTheFirstsLattice)
{
    const Piece a = sphereAt("a", 5.0, 0.25, openvdb::Vec3d(0.0)),
                b = sphereAt("b", 5.0, 0.2, openvdb::Vec3d(6.0, 0.0, 0.0));
    const Piece merged = mergePieces(a, b);
    const double ball = 4.0 / 3.0 * kPi * 125.0, lens = kPi * 26.0 * 16.0 / 12.0;
    const FieldMeasures m = measureField(merged.field);
    EXPECT_NEAR(m.volume, 2.0 * ball - lens, 0.01 * (2.0 * ball - lens));
    EXPECT_EQ(m.components, 1);
    EXPECT_EQ(merged.name, "a");
    EXPECT_DOUBLE_EQ(merged.field.voxelSize(), 0.25);
    EXPECT_EQ(gridChecksum(a.field.grid()), gridChecksum(makeSphere(5.0, 0.25).grid())) << "a was changed";
}

// Two balls apart in one piece split into two pieces, each the ball it was; one ball stays itself.
TEST(PieceEdits, SplitGivesEachSolidItsOwnPiece)
{
    const Piece a = sphereAt("pair", 4.0, 0.25, openvdb::Vec3d(0.0)),
                b = sphereAt("b", 3.0, 0.25, openvdb::Vec3d(12.0, 0.0, 0.0));
    const std::vector<Piece> parts = splitPiece(mergePieces(a, b));
    ASSERT_EQ(parts.size(), 2u);
    std::vector<double> volumes;
    for (const Piece& part : parts) {
        EXPECT_EQ(measureField(part.field).components, 1) << part.name;
        volumes.push_back(measureField(part.field).volume);
    }
    std::sort(volumes.begin(), volumes.end());
    // Each solid as it was before the merge.
    const double small = measureField(b.field).volume, large = measureField(a.field).volume;
    EXPECT_NEAR(volumes[0], small, 0.005 * small);
    EXPECT_NEAR(volumes[1], large, 0.005 * large);
    EXPECT_EQ(parts[0].name, "pair 1");
    EXPECT_EQ(parts[1].name, "pair 2");
    const std::vector<Piece> one = splitPiece(a);
    ASSERT_EQ(one.size(), 1u);
    EXPECT_EQ(one[0].name, "pair");
}

}  // namespace sculpt
