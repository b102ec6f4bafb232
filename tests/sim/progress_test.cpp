// The progress display: quiet for short runs, one redrawn line on a terminal, a line per 10 % in a log.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "run/progress.hpp"

namespace cnc::sim {
namespace {

std::size_t lines(const std::string& s) {
    return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n'));
}

TEST(Progress, RunsUnderASecondShowNothing) {
    for (ProgressStyle style : {ProgressStyle::Terminal, ProgressStyle::Log}) {
        std::ostringstream out;
        Progress p(out, style, 10.0);
        p.update(5.0, 0.4);
        p.update(10.0, 0.9);
        p.finish(10.0, 0.95);
        EXPECT_EQ(out.str(), "");
    }
}

TEST(Progress, EveryLineNamesTheRun) {
    // compare runs its architectures one after another on one stderr: each line says which one it is.
    std::ostringstream out;
    Progress p(out, ProgressStyle::Log, 10.0, "atmega");
    p.update(5.0, 2.0);
    p.finish(10.0, 4.0);
    EXPECT_EQ(out.str(),
              "cncsim: atmega: simulated 5.0 s of ~10.0 s (50 %), 2.0 s wall, about 2 s to go\n"
              "cncsim: atmega: simulated 10.0 s in 4.0 s wall\n");
}

TEST(Progress, LogHasOneLinePerTenthOfTheEstimate) {
    std::ostringstream out;
    Progress p(out, ProgressStyle::Log, 100.0);
    p.update(15.0, 0.5);  // quiet: under a second of wall time
    p.update(25.0, 1.2);  // 25 %: the 20 % line (10 % went by in the quiet second)
    EXPECT_EQ(out.str(), "cncsim: simulated 25.0 s of ~100.0 s (25 %), 1.2 s wall, about 4 s to go\n");
    p.update(29.0, 1.4);  // still below 30 %
    EXPECT_EQ(lines(out.str()), 1U);
    p.update(30.0, 1.5);
    p.update(95.0, 4.0);  // 30 % and 90 %: one line each
    EXPECT_EQ(lines(out.str()), 3U);
    p.update(150.0, 6.0);  // past the estimate: a line at 100 %, then one per doubling (200 %, 400 %, ...)
    p.update(190.0, 7.0);
    EXPECT_EQ(lines(out.str()), 4U);
    EXPECT_NE(out.str().find("simulated 150.0 s of ~100.0 s (past the estimate), 6.0 s wall\n"), std::string::npos);
    p.update(200.0, 7.5);
    EXPECT_EQ(lines(out.str()), 5U);
    p.finish(210.0, 8.0);
    EXPECT_EQ(lines(out.str()), 6U);
    EXPECT_NE(out.str().find("cncsim: simulated 210.0 s in 8.0 s wall\n"), std::string::npos);
}

TEST(Progress, TerminalRedrawsOneLineAndEndsIt) {
    std::ostringstream out;
    Progress p(out, ProgressStyle::Terminal, 10.0);
    p.update(2.0, 1.0);
    p.update(2.1, 1.1);  // within a quarter second of the last draw: not drawn
    p.update(5.0, 2.5);
    p.finish(10.0, 5.0);
    const std::string s = out.str();
    EXPECT_EQ(s.find('\r'), 0U);
    EXPECT_EQ(std::count(s.begin(), s.end(), '\r'), 3);  // two updates and the end
    EXPECT_EQ(lines(s), 1U);
    EXPECT_EQ(s.back(), '\n');
    EXPECT_NE(s.find("simulated 5.0 s of ~10.0 s (50 %), 2.5 s wall, about 2 s to go"), std::string::npos);
}

TEST(Progress, OffShowsNothing) {
    std::ostringstream out;
    Progress p(out, ProgressStyle::Off, 10.0);
    p.update(5.0, 3.0);
    p.finish(10.0, 6.0);
    EXPECT_EQ(out.str(), "");
}

}  // namespace
}  // namespace cnc::sim
