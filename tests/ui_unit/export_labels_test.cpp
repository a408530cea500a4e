// SPDX-License-Identifier: Apache-2.0
// File > Export Segmentation (Ctrl+Shift+E) in a headless window: an imported scan's document
// writes its piece as a Slicer .seg.nrrd on the kept scan's lattice, the ball's samples labelled
// as the scan has them; a document keeping no scan is refused with the reason.

#include "core/scan/scan_readers.h"
#include "tests/support/run_sculpt.h"
#include "tests/ui_unit/headless_app.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <vector>

namespace sculpt::test {
namespace {

TEST(HeadlessFiles, ExportSegmentationLabelsTheKeptScansLattice)
{
    TempDir dir;
    const int n = 48;
    std::vector<bool> ball;
    std::string bytes;
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                ball.push_back(std::hypot(i - 23.2, j - 24.1, k - 22.7) < 15.0);
                bytes.push_back(ball.back() ? char(100) : char(0));
            }
    std::ofstream(dir / "ball.raw", std::ios::binary) << bytes;
    ASSERT_EQ(runSculpt("import ball.raw --raw-dims 48,48,48 --raw-type uint8 --raw-spacing 1,1,1.5 --iso 50 -o "
                        "scan.vdb",
                        dir.path().string())
                  .exitCode,
              0);
    UiEvents events;
    events.key("E", {"ctrl", "shift"}).key("A", {"ctrl"}).text((dir / "out.seg.nrrd").string()).key("Enter");
    events.untilJobEnds().report(dir / "r.jsonl", "exported");
    ASSERT_EQ(playHeadless(dir, events, headlessOptions(dir, (dir / "scan.vdb").string())), 0);
    EXPECT_EQ(Reports(dir / "r.jsonl")["exported"]["error"], "");

    const ScanVolume labels = readScan(dir / "out.seg.nrrd"), kept = readScan(dir / "scan.vdb");
    ASSERT_EQ(labels.dims(), kept.dims());
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(labels.worldFromIndex()[r][c], kept.worldFromIndex()[r][c], 1e-9);
    std::vector<float> slice(std::size_t(n) * n);
    std::size_t both = 0, inLabels = 0, inBall = 0;
    for (int k = 0; k < n; ++k) {
        labels.readSlice(k, slice.data());
        for (std::size_t s = 0; s < slice.size(); ++s) {
            const bool labelled = slice[s] == 1.0f, inside = ball[std::size_t(k) * slice.size() + s];
            inLabels += labelled, inBall += inside, both += labelled && inside;
        }
    }
    EXPECT_GE(2.0 * double(both) / double(inLabels + inBall), 0.98);

    TempDir plain;
    UiEvents refused;
    refused.key("E", {"ctrl", "shift"}).report(plain / "r.jsonl", "refused");
    ASSERT_EQ(playHeadless(plain, refused, headlessOptions(plain)), 0);
    EXPECT_NE(Reports(plain / "r.jsonl")["refused"].dump().find("keeps no scan to label"), std::string::npos);
}

}  // namespace
}  // namespace sculpt::test
