#include <gtest/gtest.h>

#include "metrics/metrics.hpp"
#include "metrics/timing/worst_moves.hpp"

namespace cnc::metrics {
namespace {

MoveMetrics move(int index, std::optional<double> contour_um, std::optional<double> following_um,
                 std::optional<double> feed_error_pct) {
    MoveMetrics m;
    m.index = index;
    m.line = index + 2;
    m.path.contour_max_um = contour_um;
    m.path.following_max_um = following_um;
    m.timing.feed_error_pct = feed_error_pct;
    return m;
}

std::vector<std::size_t> order(const std::vector<RankedMove>& list) {
    std::vector<std::size_t> out;
    for (const RankedMove& r : list) out.push_back(r.move);
    return out;
}

std::vector<double> values(const std::vector<RankedMove>& list) {
    std::vector<double> out;
    for (const RankedMove& r : list) out.push_back(r.value);
    return out;
}

TEST(WorstMoves, TopFiveOfEachFigureWorstFirstWithoutTheMovesThatLackIt) {
    const std::vector<MoveMetrics> moves = {
        move(1, 3.0, 10.0, 0.5),         move(2, std::nullopt, 40.0, std::nullopt),  // a rapid: no feed figure
        move(3, 7.5, 20.0, -2.0),        move(4, 1.0, 5.0, 1.5),
        move(5, 7.5, std::nullopt, 0.1), move(6, 0.0, 30.0, -0.25),
        move(7, 12.0, 50.0, 3.0),        move(8, 2.0, 1.0, -3.0),
    };
    const WorstMoves w = worst_moves(moves);
    // contour: 12 (7), 7.5 (3 and 5: equal, in move order), 3 (1), 2 (8); 1 (4) and 0 (6) are 6th and 7th
    EXPECT_EQ(order(w.contour), (std::vector<std::size_t>{6, 2, 4, 0, 7}));
    EXPECT_EQ(values(w.contour), (std::vector<double>{12.0, 7.5, 7.5, 3.0, 2.0}));
    EXPECT_EQ(order(w.following), (std::vector<std::size_t>{6, 1, 5, 2, 0}));
    // feed by magnitude, sign kept: |3| (7), |-3| (8), |-2| (3), |1.5| (4), |0.5| (1)
    EXPECT_EQ(order(w.feed), (std::vector<std::size_t>{6, 7, 2, 3, 0}));
    EXPECT_EQ(values(w.feed), (std::vector<double>{3.0, -3.0, -2.0, 1.5, 0.5}));
    // Each entry names its move as the report does (index, G-code line): move 7 sits on line 9.
    EXPECT_EQ(w.contour.front().index, 7);
    EXPECT_EQ(w.contour.front().line, 9);
}

TEST(WorstMoves, AFoldKeepsOnlyTheListedNumberWhileTheMovesComeIn) {
    // 1000 moves with contour errors 1..1000 um, in rising order: each new move is the worst so far. A fold of 3
    // holds the last three, 1000, 999, 998 um (moves 999, 998, 997 by position); it never holds more than 3.
    WorstMovesFold fold(3);
    for (int i = 1; i <= 1000; ++i) {
        fold.add(move(i, static_cast<double>(i), std::nullopt, std::nullopt));
        EXPECT_LE(fold.lists().contour.size(), 3U);
    }
    EXPECT_EQ(order(fold.lists().contour), (std::vector<std::size_t>{999, 998, 997}));
    EXPECT_EQ(values(fold.lists().contour), (std::vector<double>{1000.0, 999.0, 998.0}));
    EXPECT_TRUE(fold.lists().following.empty());
}

TEST(WorstMoves, FewerMovesThanListedAndNone) {
    const std::vector<MoveMetrics> moves = {move(1, std::nullopt, std::nullopt, -0.047), move(2, 1.0, 2.0, 0.01)};
    const WorstMoves w = worst_moves(moves);
    EXPECT_EQ(order(w.contour), (std::vector<std::size_t>{1}));
    EXPECT_EQ(order(w.feed), (std::vector<std::size_t>{0, 1}));
    EXPECT_EQ(worst_moves(moves, 1).feed.size(), 1U);
    const WorstMoves none = worst_moves({});
    EXPECT_TRUE(none.contour.empty());
    EXPECT_TRUE(none.following.empty());
    EXPECT_TRUE(none.feed.empty());
}

}  // namespace
}  // namespace cnc::metrics
