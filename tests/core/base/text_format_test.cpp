// SPDX-License-Identifier: Apache-2.0
// Numbers as the window and the command line print them.

#include "core/base/text_format.h"

#include <gtest/gtest.h>

namespace sculpt {
namespace {

TEST(TextFormat, CountsAreGroupedByThousands)
{
    EXPECT_EQ(formatCount(0), "0");
    EXPECT_EQ(formatCount(999), "999");
    EXPECT_EQ(formatCount(1000), "1,000");
    EXPECT_EQ(formatCount(2097510), "2,097,510");
    EXPECT_EQ(formatCount(18446744073709551615ull), "18,446,744,073,709,551,615");
}

TEST(TextFormat, SecondsAreRoundedToTheMillisecond)
{
    EXPECT_EQ(formatSeconds(8.5334), "8.533");
    EXPECT_EQ(formatSeconds(0.2706), "0.271");
    EXPECT_EQ(formatSeconds(12.0), "12");
}

}  // namespace
}  // namespace sculpt
