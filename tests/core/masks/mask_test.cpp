// SPDX-License-Identifier: Apache-2.0
// The mask holds the surface where it is 1, bit for bit, through every kind of edit (a brush's
// stamps, whole-model smoothing, a morph), is journalled with the surface, and round-trips
// through a document.

#include "core/brushes/brush.h"
#include "core/field/grid_checksum.h"
#include "core/field/leaf_journal.h"
#include "core/field/surface_mask.h"
#include "core/io/vdb_file.h"
#include "core/masks/mask_edit.h"
#include "core/masks/mask_operations.h"
#include "core/motion/morph.h"
#include "core/motion/surface_flows.h"
#include "core/primitives/analytic_shapes.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <limits>
#include <map>

namespace sculpt {
namespace {

using openvdb::Coord;
using openvdb::Vec3d;

struct VoxelState {
    float value;
    bool active;
    bool operator==(const VoxelState& o) const { return value == o.value && active == o.active; }
};

/// Masks the half x < 0 (by each voxel's closest surface point), without a journal.
void maskHalf(FieldImage& field)
{
    rewriteMask(field, maskDomain(field), nullptr,
                [](const Coord& ijk, const MaskSite& site) { return site.footWorld(ijk).x() < 0.0 ? 1.0 : 0.0; });
}

/// Every voxel of the field's leaves whose mask (its closest surface point's, painted) is 1, as it is now.
std::map<Coord, VoxelState> heldVoxels(const FieldImage& field)
{
    std::map<Coord, VoxelState> held;
    const MaskReader reader(*field.mask());
    const auto acc = field.grid().getConstAccessor();
    for (auto leaf = field.grid().tree().cbeginLeaf(); leaf; ++leaf)
        for (auto it = leaf->beginValueAll(); it; ++it)
            if (reader.at(it.getCoord()) >= 1.0)
                held[it.getCoord()] = {acc.getValue(it.getCoord()), acc.isValueOn(it.getCoord())};
    return held;
}

/// Held voxels that changed, and how many voxels with x > 0 changed (the edit did act).
struct Changes {
    std::size_t held = 0, free = 0;
};

Changes changesSince(const std::map<Coord, VoxelState>& held, const openvdb::FloatGrid& before, const FieldImage& after)
{
    Changes changes;
    const auto acc = after.grid().getConstAccessor();
    for (const auto& [ijk, state] : held) changes.held += !(VoxelState{acc.getValue(ijk), acc.isValueOn(ijk)} == state);
    const auto was = before.getConstAccessor();
    for (auto it = after.grid().cbeginValueOn(); it; ++it)
        changes.free += it.getCoord().x() > 0 && was.getValue(it.getCoord()) != *it;
    return changes;
}

class MaskedHalf : public ::testing::Test {
protected:
    void SetUp() override
    {
        maskHalf(ball);
        ASSERT_NE(ball.mask(), nullptr);
        held = heldVoxels(ball);
        ASSERT_GT(held.size(), 1000u);
        before = ball.grid().deepCopy();
    }
    FieldImage ball = makeSphere(8.0, 0.5);
    std::map<Coord, VoxelState> held;
    openvdb::FloatGrid::Ptr before;
};

TEST_F(MaskedHalf, SmoothingLeavesTheMaskedHalfBitForBit)
{
    smooth(ball, 20);
    const Changes changes = changesSince(held, *before, ball);
    EXPECT_EQ(changes.held, 0u);
    EXPECT_GT(changes.free, 1000u);
}

TEST_F(MaskedHalf, InflateStrokesAcrossThePlaneLeaveTheMaskedHalfBitForBit)
{
    BrushSettings brush;
    brush.tool = BrushTool::Inflate;
    brush.radiusWorld = 3.0;
    brush.strength = 1.0;
    LeafJournal journal;
    for (double y = -6.0; y <= 6.0; y += 1.0) {
        BrushStamp stamp;
        stamp.centreWorld = stamp.previousWorld = Vec3d(0.0, y, std::sqrt(64.0 - y * y));
        applyStamp(ball, brush, stamp, &journal);
    }
    const Changes changes = changesSince(held, *before, ball);
    EXPECT_EQ(changes.held, 0u);
    EXPECT_GT(changes.free, 100u);
    journal.swap(ball);  // undo
    EXPECT_EQ(gridChecksum(ball.grid()), gridChecksum(*before));
}

TEST_F(MaskedHalf, AMorphIntoABoxLeavesTheMaskedHalfBitForBitInEveryFrame)
{
    MorphOptions options;
    options.frames = 3;
    int frames = 0;
    morph(ball, makeBox(7.0, 0.5), options, [&](const MorphFrame& frame) {
        const Changes changes = changesSince(held, *before, frame.field);
        EXPECT_EQ(changes.held, 0u) << "frame " << frame.index;
        if (frame.index == 2) {
            EXPECT_GT(changes.free, 1000u);
        }
        ++frames;
    });
    EXPECT_EQ(frames, 3);
}

TEST_F(MaskedHalf, TheMaskIsSavedAndOpenedWithItsSurface)
{
    const auto path = std::filesystem::path(::testing::TempDir()) / "masked_half.vdb";
    writeFieldImage(ball, path);
    const FieldImage opened = readFieldImage(path);
    ASSERT_NE(opened.mask(), nullptr);
    EXPECT_EQ(gridChecksum(*opened.mask()), gridChecksum(*ball.mask()));
    EXPECT_EQ(gridChecksum(opened.grid()), gridChecksum(ball.grid()));
    std::filesystem::remove(path);
}

TEST_F(MaskedHalf, MaskOperationsUndoBitForBitWithTheSurface)
{
    applyMaskOperation(ball, MaskOperation::Blur, 2, nullptr);  // a soft edge: sharpening changes it
    const std::uint64_t mask0 = gridChecksum(*ball.mask()), surface0 = gridChecksum(ball.grid());
    for (MaskOperation operation : {MaskOperation::Invert, MaskOperation::Blur, MaskOperation::Sharpen,
                                    MaskOperation::Grow, MaskOperation::Shrink, MaskOperation::Clear}) {
        LeafJournal journal;
        applyMaskOperation(ball, operation, 2, &journal);
        EXPECT_FALSE(journal.empty()) << maskOperationName(operation);
        journal.swap(ball);
        ASSERT_NE(ball.mask(), nullptr) << maskOperationName(operation);
        EXPECT_EQ(gridChecksum(*ball.mask()), mask0) << maskOperationName(operation);
        EXPECT_EQ(gridChecksum(ball.grid()), surface0);
    }
}

TEST_F(MaskedHalf, InvertingFreesTheMaskedHalfAndHoldsTheOther)
{
    applyMaskOperation(ball, MaskOperation::Invert, 1, nullptr);
    const MaskReader reader(*ball.mask());
    const auto& xform = ball.grid().transform();
    EXPECT_EQ(reader.at(xform.worldToIndexCellCentered(Vec3d(-8.0, 0.0, 0.0))), 0.0);
    EXPECT_EQ(reader.at(xform.worldToIndexCellCentered(Vec3d(8.0, 0.0, 0.0))), 1.0);
}

TEST_F(MaskedHalf, AMaskOfValuesThatAreNoSharesIsReadAsShares)
{
    auto acc = ball.mutableMask().getAccessor();
    const Coord a(0, 0, 16), b(1, 0, 16), c(2, 0, 16);  // near the ball's top, on its leaves
    acc.setValueOn(a, std::numeric_limits<float>::quiet_NaN());
    acc.setValueOn(b, 2.5f);
    acc.setValueOn(c, -1.0f);
    const auto path = std::filesystem::path(::testing::TempDir()) / "odd_mask.vdb";
    writeFieldImage(ball, path);
    const FieldImage opened = readFieldImage(path);
    ASSERT_NE(opened.mask(), nullptr);
    const auto read = opened.mask()->getConstAccessor();
    EXPECT_EQ(read.getValue(a), 0.0f);
    EXPECT_EQ(read.getValue(b), 1.0f);
    EXPECT_EQ(read.getValue(c), 0.0f);
    std::filesystem::remove(path);
}

}  // namespace
}  // namespace sculpt
