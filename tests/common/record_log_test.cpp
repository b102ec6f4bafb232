#include "common/record_log.hpp"

#include <gtest/gtest.h>

#include <iterator>

namespace cnc {
namespace {

RecordLog<int> log_of(int n) {
    RecordLog<int> log;
    for (int i = 0; i < n; ++i) log.push_back(10 * i);
    return log;
}

TEST(RecordLog, DroppedRecordsLeaveTheOthersAtTheirIndices) {
    RecordLog<int> log = log_of(5);
    log.drop_before(2);
    EXPECT_EQ(log.first(), 2U);
    EXPECT_EQ(log.size(), 5U);
    EXPECT_EQ(log[2], 20);
    EXPECT_EQ(log[4], 40);
    EXPECT_EQ(std::distance(log.begin(), log.end()), 3);
    EXPECT_EQ(log.front(), 20);
    EXPECT_EQ(log.back(), 40);
    log.push_back(50);
    EXPECT_EQ(log.size(), 6U);
    EXPECT_EQ(log[5], 50);
}

TEST(RecordLog, DroppingBeforeAnEarlierIndexKeepsWhatIsLeft) {
    RecordLog<int> log = log_of(4);
    log.drop_before(3);
    log.drop_before(1);
    EXPECT_EQ(log.first(), 3U);
    EXPECT_EQ(log[3], 30);
}

TEST(RecordLog, DroppingPastTheEndDropsEverythingAndCountsOn) {
    RecordLog<int> log = log_of(3);
    log.drop_before(7);
    EXPECT_EQ(log.first(), 3U);
    EXPECT_EQ(log.size(), 3U);
    EXPECT_FALSE(log.empty());
    EXPECT_EQ(log.begin(), log.end());
    log.push_back(30);
    EXPECT_EQ(log[3], 30);
}

}  // namespace
}  // namespace cnc
