// SPDX-License-Identifier: Apache-2.0
#include "core/field/grid_checksum.h"
#include "core/field/leaf_journal.h"
#include "core/primitives/analytic_shapes.h"

#include <gtest/gtest.h>

namespace sculpt {
namespace {

using LeafT = openvdb::FloatTree::LeafNodeType;

/// Writes one inside voxel into a new leaf at `origin`, saving the leaf first as an edit does.
void editLeaf(FieldImage& field, LeafJournal& journal, const openvdb::Coord& origin)
{
    journal.save(field.grid().tree(), origin);
    auto acc = field.mutableGrid().getAccessor();
    acc.touchLeaf(origin)->setValueOn(origin, -0.1f);
}

TEST(LeafJournal, UndoOfLeavesGrownIntoEmptySpaceRestoresTheTreeStructure)
{
    FieldImage field = makeSphere(10.0, 1.0);
    const std::uint64_t before = gridChecksum(field.grid());
    const openvdb::Index64 nodesBefore = field.grid().tree().nonLeafCount();
    // Far outside: the first leaf splits a background tile into a lower internal node; the
    // second is then saved as one of that node's tiles. Restoring both must not split it again.
    LeafJournal journal;
    editLeaf(field, journal, openvdb::Coord(512, 0, 0));
    editLeaf(field, journal, openvdb::Coord(520, 0, 0));
    editLeaf(field, journal, openvdb::Coord(64, 0, 0));
    editLeaf(field, journal, openvdb::Coord(72, 8, 0));
    ASSERT_GT(field.grid().tree().nonLeafCount(), nodesBefore);
    journal.swap(field);
    EXPECT_EQ(field.grid().tree().nonLeafCount(), nodesBefore);
    EXPECT_EQ(gridChecksum(field.grid()), before);
    journal.swap(field);  // redo
    EXPECT_NE(gridChecksum(field.grid()), before);
    journal.swap(field);
    EXPECT_EQ(gridChecksum(field.grid()), before);
}

}  // namespace
}  // namespace sculpt
