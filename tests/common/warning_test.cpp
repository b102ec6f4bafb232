#include <gtest/gtest.h>

#include "common/warning.hpp"

namespace cnc {
namespace {

std::vector<Warning> ocr_lines(int first_line, int n) {
    std::vector<Warning> w;
    for (int i = 0; i < n; ++i) {
        w.push_back({"ocr0a_range", "job.nc:" + std::to_string(first_line + i), "OCR0A " + std::to_string(i)});
    }
    return w;
}

TEST(WarningGroups, OneGroupPerKindInOrderOfFirstAppearance) {
    std::vector<Warning> w = ocr_lines(10, 5);
    w.insert(w.begin() + 2, {"late_chords", "", "2 chords started late"});
    w.push_back({"ocr2a_range", "job.nc:40", "OCR2A"});
    const std::vector<WarningGroup> g = group_warnings(w);
    ASSERT_EQ(g.size(), 3U);
    EXPECT_EQ(g[0].kind, "ocr0a_range");
    EXPECT_EQ(g[0].count, 5U);
    EXPECT_EQ(g[0].first, (std::vector<std::string>{"job.nc:10", "job.nc:11", "job.nc:12"}));
    EXPECT_EQ(g[0].message, "OCR0A 0");
    EXPECT_EQ(g[0].members, (std::vector<std::size_t>{0, 1, 3, 4, 5}));
    EXPECT_EQ(g[1].kind, "late_chords");
    EXPECT_EQ(g[1].count, 1U);
    EXPECT_TRUE(g[1].first.empty());
    EXPECT_EQ(g[1].members, (std::vector<std::size_t>{2}));
    EXPECT_EQ(g[2].kind, "ocr2a_range");
    EXPECT_EQ(g[2].first, (std::vector<std::string>{"job.nc:40"}));
    EXPECT_TRUE(group_warnings({}).empty());
}

TEST(WarningGroups, SummaryLineKeepsASingleWarningAsWorded) {
    const std::vector<Warning> one = {{"long_move", "t.nc:1", "G01 count 67200 exceeds"}};
    EXPECT_EQ(summary_line(group_warnings(one).at(0)), "t.nc:1: G01 count 67200 exceeds");
    EXPECT_EQ(to_string(one[0]), "t.nc:1: G01 count 67200 exceeds");
    const std::vector<Warning> count = {{"fifo_drops", "", "12 rate frames dropped"}};
    EXPECT_EQ(summary_line(group_warnings(count).at(0)), "12 rate frames dropped");
    EXPECT_EQ(to_string(count[0]), "12 rate frames dropped");
}

TEST(WarningGroups, SummaryLineOfSeveralCountsThemAndNamesTheFirstThreePlaces) {
    EXPECT_EQ(summary_line(group_warnings(ocr_lines(10, 471)).at(0)),
              "471 x ocr0a_range at job.nc:10, job.nc:11, job.nc:12, ...; first: OCR0A 0");
    EXPECT_EQ(summary_line(group_warnings(ocr_lines(7, 2)).at(0)),
              "2 x ocr0a_range at job.nc:7, job.nc:8; first: OCR0A 0");
    const std::vector<Warning> unplaced = {{"k", "", "a"}, {"k", "", "b"}};
    EXPECT_EQ(summary_line(group_warnings(unplaced).at(0)), "2 x k; first: a");
}

}  // namespace
}  // namespace cnc
