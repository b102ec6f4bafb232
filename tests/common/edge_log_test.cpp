#include <gtest/gtest.h>

#include "common/edge_log.hpp"
#include "common/units.hpp"

TEST(EdgeLog, LevelsAndEdgeLists) {
    cnc::EdgeLog log{"step_x", false, {}};
    log.add(100, true);
    log.add(300, false);
    log.add(500, true);
    EXPECT_FALSE(log.level_at(99));
    EXPECT_TRUE(log.level_at(100));
    EXPECT_FALSE(log.level_at(400));
    EXPECT_EQ(log.rising(), (std::vector<cnc::TimePs>{100, 500}));
    EXPECT_EQ(log.falling(), (std::vector<cnc::TimePs>{300}));
}

TEST(EdgeLog, TakeBeforeHandsOverTheEarlierEdgesAndKeepsTheLevelTheyLeave) {
    cnc::EdgeLog log{"step_x", false, {}};
    log.add(100, true);
    log.add(300, false);
    log.add(500, true);
    const cnc::EdgeLog taken = log.take_before(300);  // an edge at the cut stays
    EXPECT_EQ(taken.name, "step_x");
    EXPECT_FALSE(taken.initial);
    EXPECT_EQ(taken.rising(), (std::vector<cnc::TimePs>{100}));
    EXPECT_TRUE(log.initial);
    EXPECT_EQ(log.falling(), (std::vector<cnc::TimePs>{300}));
    EXPECT_EQ(log.rising(), (std::vector<cnc::TimePs>{500}));
    EXPECT_TRUE(log.take_before(50).edges.empty());
    EXPECT_TRUE(log.initial);  // nothing taken: the level stays
}

TEST(Units, CyclesToPsIsExactForFpgaAndAvrClocksAndDriftFreeForOthers) {
    EXPECT_EQ(cnc::cycles_to_ps(15'625, 50'000'000), 312'500'000);  // 312.5 us
    EXPECT_EQ(cnc::cycles_to_ps(1, 16'000'000), 62'500);            // 62.5 ns AVR cycle
    EXPECT_EQ(cnc::cycles_to_ps(24'000'000, 24'000'000), cnc::kPsPerSec);
    EXPECT_EQ(cnc::cycles_to_ps(208, 24'000'000), 8'666'666);               // one CP2102 bit at 115 384.6 Bd
    EXPECT_EQ(cnc::cycles_to_ps(20'800'000, 24'000'000), 866'666'666'666);  // no int64 overflow mid-second
    EXPECT_EQ(cnc::cycles_to_ps(49'999'999, 50'000'000), 999'999'980'000);
    EXPECT_EQ(cnc::first_edge_after(20'000, 20'000), 2);  // a change on an edge is seen by the next
    EXPECT_EQ(cnc::first_edge_after(19'999, 20'000), 1);
}
