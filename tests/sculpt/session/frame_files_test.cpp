// SPDX-License-Identifier: Apache-2.0
// Frames in a directory are played in the order people count them, whatever their digits' width.

#include "sculpt/session/frame_files.h"
#include "tests/support/temp_dir.h"

#include <gtest/gtest.h>

#include <fstream>

namespace sculpt {
namespace {

TEST(FrameFiles, NumberedNamesSortByTheirNumbers)
{
    EXPECT_TRUE(numberedNameLess("frame_9999.vdb", "frame_10000.vdb"));
    EXPECT_FALSE(numberedNameLess("frame_10000.vdb", "frame_9999.vdb"));
    EXPECT_TRUE(numberedNameLess("frame2.vdb", "frame10.vdb"));
    EXPECT_TRUE(numberedNameLess("frame_0002.vdb", "frame_0010.vdb"));
    EXPECT_TRUE(numberedNameLess("a.vdb", "b.vdb"));
    EXPECT_TRUE(numberedNameLess("frame_7.vdb", "frame_07.vdb")) << "the same number: fewer zeros first";
    EXPECT_FALSE(numberedNameLess("frame_1.vdb", "frame_1.vdb"));

    const test::TempDir dir;
    for (const char* name : {"frame_10000.vdb", "frame_0002.vdb", "frame_9999.vdb", "notes.txt"})
        std::ofstream(dir / name) << "x";
    const std::vector<std::filesystem::path> frames = documentsIn(dir.path());
    ASSERT_EQ(frames.size(), 3u);
    EXPECT_EQ(frames[0].filename(), "frame_0002.vdb");
    EXPECT_EQ(frames[1].filename(), "frame_9999.vdb");
    EXPECT_EQ(frames[2].filename(), "frame_10000.vdb");
}

}  // namespace
}  // namespace sculpt
