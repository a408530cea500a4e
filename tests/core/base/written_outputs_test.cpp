// SPDX-License-Identifier: Apache-2.0
// What a long write makes is taken back when it fails, and a sequence the disk cannot hold is
// refused once its first item shows the size of the rest.

#include "core/base/errors.h"
#include "core/base/written_outputs.h"
#include "tests/support/temp_dir.h"

#include <gtest/gtest.h>

#include <fstream>

namespace sculpt {
namespace {

namespace fs = std::filesystem;

TEST(WrittenOutputs, AFailureTakesBackWhatItMadeAndKeepsWhatWasThere)
{
    const test::TempDir dir;
    std::ofstream(dir / "before.txt") << "the user's";
    {
        WrittenOutputs outputs;
        outputs.directory(dir / "frames");
        std::ofstream(outputs.file(dir / "frames" / "frame_0000.vdb")) << "frame";
        std::ofstream(outputs.file(dir / "before.txt")) << "overwritten";
    }  // not kept
    EXPECT_FALSE(fs::exists(dir / "frames"));
    EXPECT_TRUE(fs::exists(dir / "before.txt"));
    {
        WrittenOutputs outputs;
        outputs.directory(dir / "kept");
        std::ofstream(outputs.file(dir / "kept" / "a")) << "a";
        outputs.keep();
    }
    EXPECT_TRUE(fs::exists(dir / "kept" / "a"));
}

TEST(WrittenOutputs, ASequenceTheDiskCannotHoldIsRefusedAfterItsFirstItem)
{
    const test::TempDir dir;
    WrittenOutputs outputs;
    outputs.directory(dir / "frames");
    std::ofstream(outputs.file(dir / "frames" / "frame_0000.vdb")) << std::string(1000, 'x');
    EXPECT_NO_THROW(outputs.requireRoomFor(9, 1.0, "the other 9 frames"));
    try {
        outputs.requireRoomFor(1000000000000000LL, 2.0, "the other frames");  // 2 EB
        FAIL() << "two exabytes fit";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find((dir / "frames").string() + ": the other frames need about"), std::string::npos) << what;
        EXPECT_NE(what.find("is free there"), std::string::npos) << what;
    }
}

}  // namespace
}  // namespace sculpt
