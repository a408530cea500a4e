// The document without a window: undo and redo restore the grid bit for bit, and the modified
// mark follows the saved state through edits, undo, redo and saves.

#include "core/field/grid_checksum.h"
#include "tests/support/temp_dir.h"
#include "ui/document/document.h"

#include <gtest/gtest.h>

namespace sculpt::ui {
namespace {

using test::TempDir;

std::uint64_t checksumOf(const Document& document) { return gridChecksum(document.session().field().grid()); }

FieldImage ballOfRadius(double radius)
{
    return Document::create(NewShape{0, radius, 0.5}).session().field().deepCopy();
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

}  // namespace
}  // namespace sculpt::ui
