// SPDX-License-Identifier: Apache-2.0
// A label map's warnings alike (each piece's debris, say) are said three times and then counted;
// warnings of other kinds, and those of fewer pieces, are said in full and in order.

#include "core/base/warning_summary.h"

#include <gtest/gtest.h>

namespace sculpt {
namespace {

TEST(WarningSummary, AlikeWarningsAreSaidThreeTimesThenCounted)
{
    std::vector<std::string> warnings{"atlas.nii: its sform is mirrored against its qform"};
    for (int i = 0; i < 2000; ++i)
        warnings.push_back("piece 'label " + std::to_string(i + 1) + "': removed " + std::to_string(i % 7 + 1) +
                           " voxels of debris");
    warnings.push_back("piece 'label 7': the mesh is not closed");
    const std::vector<std::string> said = summarisedWarnings(warnings);
    ASSERT_EQ(said.size(), 6u);
    EXPECT_EQ(said[0], warnings[0]);
    EXPECT_EQ(said[1], warnings[1]);
    EXPECT_EQ(said[3], warnings[3]);
    EXPECT_EQ(said[4], "... and 1997 more like it (--verbose lists them)");
    EXPECT_EQ(said[5], warnings.back());
    const std::vector<std::string> few(warnings.begin(), warnings.begin() + 4);
    EXPECT_EQ(summarisedWarnings(few), few) << "three alike are said in full";
}

}  // namespace
}  // namespace sculpt
