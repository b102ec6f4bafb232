// The LCD transcript keeps contents that stayed kLcdSettleS (50 ms) or more, stamped with the time they appeared.
#include <gtest/gtest.h>

#include "lathe/core/lcd_transcript.hpp"

namespace {

using cnc::lathe::LcdLines;
using cnc::lathe::LcdScreen;
using cnc::lathe::LcdTranscript;

TEST(LcdTranscript, KeepsSettledScreensOnly) {
    LcdTranscript t;
    t.changed(0.000, LcdLines{"c", ""});  // a clear, then the prompt written 1 ms later
    t.changed(0.001, LcdLines{"cut", ""});
    t.tick(0.050);  // 49 ms: not yet settled
    EXPECT_TRUE(t.screens(0.050).empty());
    t.tick(0.052);
    ASSERT_EQ(t.screens(0.052).size(), 1U);
    EXPECT_DOUBLE_EQ(t.screens(0.052)[0].t_s, 0.001);
    EXPECT_EQ(t.screens(0.052)[0].lines[0], "cut");
    t.changed(1.000, LcdLines{"flash", ""});  // shown 10 ms only
    t.changed(1.010, LcdLines{"cut", ""});    // back to what was read: not a new screen
    t.changed(2.000, LcdLines{"move", ""});
    const auto& s = t.screens(2.051);  // the end of the run: what shows then counts once settled
    ASSERT_EQ(s.size(), 2U);
    EXPECT_EQ(s[1].lines[0], "move");
    EXPECT_DOUBLE_EQ(s[1].t_s, 2.000);
}

// The screens' bars stay in one column when the times gain a digit (9.999 s -> 10.000 s -> 100.000 s): every line
// is as long as the others, the times right-aligned.
TEST(LcdTranscript, TextKeepsTheScreensInOneColumn) {
    const std::vector<LcdScreen> screens = {{0.001, LcdLines{"cut", "1"}},
                                            {9.9994, LcdLines{"cut", "2"}},
                                            {10.0, LcdLines{"cut", "3"}},
                                            {100.25, LcdLines{"cut", "4"}}};
    EXPECT_EQ(cnc::lathe::transcript_text(screens),
              "    0.001 s  |cut|1|\n"
              "    9.999 s  |cut|2|\n"
              "   10.000 s  |cut|3|\n"
              "  100.250 s  |cut|4|\n");
    EXPECT_EQ(cnc::lathe::transcript_text({}), "");
}

}  // namespace
