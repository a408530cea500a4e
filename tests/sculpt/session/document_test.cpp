// SPDX-License-Identifier: Apache-2.0
// The document without a window: undo and redo restore the grid bit for bit, and the modified
// mark follows the saved state through edits, undo, redo and saves.

#include "core/field/grid_checksum.h"
#include "core/io/vdb_file.h"
#include "sculpt/session/document.h"
#include "tests/support/temp_dir.h"

#include <gtest/gtest.h>

namespace sculpt {
namespace {

using test::TempDir;

std::uint64_t checksumOf(const Document& document) { return gridChecksum(document.session().field().grid()); }

FieldImage ballOfRadius(double radius)
{
    return Document::create(NewShape{NewShape::Kind::Sphere, radius, 0.5}).session().field().deepCopy();
}

TEST(Document, UndoAndRedoRestoreTheGridAndTheModifiedMarkFollowsTheSavedState)
{
    TempDir dir;
    Document document(ballOfRadius(6.0), dir / "ball.vdb");
    const std::uint64_t opened = checksumOf(document);
    EXPECT_FALSE(document.modified());
    EXPECT_EQ(document.title(), "ball.vdb");

    document.replaceField(ballOfRadius(7.0), "grow");
    const std::uint64_t grown = checksumOf(document);
    EXPECT_NE(grown, opened);
    EXPECT_TRUE(document.modified());
    EXPECT_EQ(document.title(), "ball.vdb *");
    ASSERT_EQ(document.undoLabels(), std::vector<std::string>{"grow"});

    ASSERT_TRUE(document.undo());
    EXPECT_EQ(checksumOf(document), opened);
    EXPECT_FALSE(document.modified()) << "back at the saved state";
    EXPECT_EQ(document.redoLabels(), std::vector<std::string>{"grow"});
    ASSERT_TRUE(document.redo());
    EXPECT_EQ(checksumOf(document), grown);
    EXPECT_TRUE(document.modified());

    document.save();
    EXPECT_FALSE(document.modified());
    ASSERT_TRUE(document.undo());
    EXPECT_TRUE(document.modified()) << "the file holds the grown ball";
    ASSERT_TRUE(document.redo());
    EXPECT_FALSE(document.modified());
    EXPECT_FALSE(document.redo()) << "nothing left to redo";
}

TEST(Document, AnEditAfterUndoDropsTheRedoSteps)
{
    Document document(ballOfRadius(6.0));
    document.replaceField(ballOfRadius(7.0), "grow");
    ASSERT_TRUE(document.undo());
    document.replaceField(ballOfRadius(5.0), "shrink");
    EXPECT_TRUE(document.redoLabels().empty());
    EXPECT_EQ(document.undoLabels(), std::vector<std::string>{"shrink"});
    EXPECT_EQ(checksumOf(document), gridChecksum(ballOfRadius(5.0).grid()));
}

std::uint64_t pieceChecksum(const Document& document, std::size_t i)
{
    return gridChecksum(document.pieces()[i].session->field().grid());
}

// One history across pieces: a look change, a delete, a move that dents another piece and an
// edit of the piece being sculpted each undo as one step, whichever piece is active; a deleted
// piece comes back with its voxels; the piece sculpted stays the same one.
TEST(Document, PieceEditsUndoAsOneStepEachAcrossPieces)
{
    TempDir dir;
    std::vector<Piece> pieces{
        {{"body"}, ballOfRadius(6.0)}, {{"eye"}, ballOfRadius(3.0)}, {{"hat"}, ballOfRadius(2.0)}};
    pieces[1].placement.setTranslation(openvdb::Vec3d(8.0, 0.0, 0.0));
    Document document(std::move(pieces), dir / "figure.vdb");
    const std::uint64_t eye = pieceChecksum(document, 1), hat = pieceChecksum(document, 2);
    document.setActivePiece(2);
    EXPECT_EQ(document.session().field().grid().activeVoxelCount(),
              document.pieces()[2].session->field().grid().activeVoxelCount());

    std::vector<PieceLook> looks;
    for (const DocumentPiece& piece : document.pieces()) looks.push_back(piece.look);
    looks[0].name = "torso";
    looks[1].visible = false;
    document.setLooks(looks, "rename and hide");
    document.replacePieces({0}, {}, "delete 'torso'");
    ASSERT_EQ(document.pieces().size(), 2u);
    EXPECT_EQ(document.pieces()[document.activePiece()].look.name, "hat") << "the hat is still sculpted";
    openvdb::Mat4d moved = openvdb::Mat4d::identity();
    moved.setTranslation(openvdb::Vec3d(5.0, 0.0, 0.0));
    std::vector<std::pair<std::size_t, FieldImage>> dents;
    dents.emplace_back(0, ballOfRadius(2.5));
    document.movePiece(1, moved, std::move(dents), "move 'hat'");
    document.replaceField(ballOfRadius(2.2), "grow the hat");
    EXPECT_EQ(document.undoLabels().size(), 4u);
    EXPECT_EQ(document.freeName("eye"), "eye 2");
    EXPECT_EQ(document.freeName("tail"), "tail");

    ASSERT_TRUE(document.undo());
    EXPECT_EQ(checksumOf(document), hat) << "the hat as it was";
    ASSERT_TRUE(document.undo());
    EXPECT_EQ(pieceChecksum(document, 0), eye) << "the dent undone with the move";
    EXPECT_EQ(document.pieces()[1].look.placement, openvdb::Mat4d::identity());
    ASSERT_TRUE(document.undo());
    ASSERT_EQ(document.pieces().size(), 3u) << "the deleted piece is back";
    EXPECT_EQ(document.pieces()[0].look.name, "torso");
    ASSERT_TRUE(document.undo());
    EXPECT_EQ(document.pieces()[0].look.name, "body");
    EXPECT_TRUE(document.pieces()[1].look.visible);
    EXPECT_EQ(document.pieces()[document.activePiece()].look.name, "hat");
    EXPECT_FALSE(document.modified());

    while (document.redo()) {}
    EXPECT_EQ(document.pieces().size(), 2u);
    EXPECT_NE(pieceChecksum(document, 0), eye);
    EXPECT_NE(checksumOf(document), hat);
    document.save();
    const VdbPieces saved = readVdbPieces(dir / "figure.vdb");
    ASSERT_EQ(saved.pieces.size(), 2u);
    EXPECT_EQ(saved.pieces[0].name, "eye");
    EXPECT_FALSE(saved.pieces[0].visible);
    EXPECT_EQ(saved.pieces[1].placement, moved);
    EXPECT_EQ(gridChecksum(saved.pieces[1].field.grid()), checksumOf(document));
}

}  // namespace
}  // namespace sculpt
