// The interpreter read a line at a time (host::GcodeStream, what fpga-uart streams its job with) and the host
// waits laid unit by unit (host::UnitWaitLayer).
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "host/core/host_waits.hpp"
#include "host_test_util.hpp"

namespace cnc::host {
namespace {

using test::bad_input_message;
using test::expect_point;

// The line endings of files with LF (LF, CR LF, CR CR LF) after a byte-order mark, a dwell, an arc, a Z-only
// move and an ignored word: 10 lines up to M30, of which 4 make XY moves.
const std::string kJob =
    "\xEF\xBB\xBF(job)\nG21 G90 M3 S100\r\nG0 X1 Y1\r\r\nG4 P0.5\nG1 X11 F600 T1\nG2 X21 I5\nG1 Z5 F60\n"
    "G1 Y11 F1200\n\nM30\nG1 X99\n";

std::vector<ProgrammedMove> streamed(GcodeStream& stream) {
    std::vector<ProgrammedMove> moves;
    for (std::optional<ProgrammedMove> m = stream.next(); m; m = stream.next()) moves.push_back(*m);
    return moves;
}

TEST(GcodeStream, HandsOverTheMovesTheWholeProgramHasAndKeepsOnlyItsSummary) {
    std::istringstream in(kJob);
    GcodeStream stream(in, "t.nc", {}, false);
    const std::vector<ProgrammedMove> moves = streamed(stream);
    const Program p = stream.take();
    // The job read by hand: G0 X1 Y1 (line 3), G1 X11 (5), the half circle to X21 about (16, 1) (6), G1 Y11 (8).
    ASSERT_EQ(moves.size(), 4u);
    EXPECT_EQ(moves[0].line, 3);
    expect_point(moves[0].path.end, 1, 1);
    EXPECT_EQ(moves[1].line, 5);
    EXPECT_TRUE(moves[2].path.is_arc);
    expect_point(moves[2].path.center, 16, 1);
    expect_point(moves[3].path.end, 21, 11);
    EXPECT_EQ(moves[3].line, 8);
    EXPECT_TRUE(p.moves.empty());
    EXPECT_EQ(p.move_count, 4u);
    EXPECT_EQ(p.lines, 10);  // up to M30; line 11 is not read
    // The dwell before move 1 (0.5 s) and the Z move of 5 mm at F60 (5 s) before move 3.
    ASSERT_EQ(p.waits.size(), 2u);
    EXPECT_EQ(p.waits[0].before_move, 1u);
    EXPECT_DOUBLE_EQ(p.waits[0].seconds, 0.5);
    EXPECT_EQ(p.waits[1].before_move, 3u);
    EXPECT_DOUBLE_EQ(p.waits[1].seconds, 5.0);
    EXPECT_DOUBLE_EQ(p.z_travel_mm, 5.0);
    ASSERT_EQ(p.ignored.size(), 1u);
    EXPECT_EQ(p.ignored[0].word, "T1");

    // The whole program has the same moves, kept.
    const Program whole = test::run_gcode(kJob);
    ASSERT_EQ(whole.moves.size(), 4u);
    EXPECT_EQ(whole.move_count, 4u);
    for (std::size_t i = 0; i < moves.size(); ++i) {
        EXPECT_EQ(whole.moves[i].line, moves[i].line);
        expect_point(whole.moves[i].path.end, moves[i].path.end.x_mm, moves[i].path.end.y_mm);
        EXPECT_EQ(whole.moves[i].feed_mm_per_min, moves[i].feed_mm_per_min);
    }
}

TEST(GcodeStream, ThrowsTheFilesProblemsAtItsEndAfterTheMovesBefore) {
    std::istringstream in("G1 X1 F100\nG33 X2\nG1 X3\nM84\n");
    GcodeStream stream(in, "t.nc", {}, false);
    ASSERT_TRUE(stream.next().has_value());  // line 1
    ASSERT_TRUE(stream.next().has_value());  // line 3
    const std::string msg = bad_input_message([&] { (void)stream.next(); });
    EXPECT_EQ(msg.rfind("t.nc:2: unsupported word 'G33'", 0), 0u) << msg;
    EXPECT_NE(msg.find("t.nc:4: unsupported word 'M84'"), std::string::npos) << msg;
}

TEST(GcodeStream, AMissingFileIsBadInput) {
    const std::string msg = bad_input_message([] { GcodeStream s("/nonexistent/gcode_stream_test.nc", {}, false); });
    EXPECT_NE(msg.find("/nonexistent/gcode_stream_test.nc"), std::string::npos) << msg;
    EXPECT_NE(msg.find("cannot open"), std::string::npos) << msg;
}

TEST(UnitWaitLayer, EachWaitBeforeTheFirstUnitOfItsMoveOrTheNextMoveWithUnits) {
    // Waits: 1 s before move 0, 2 s before move 1, 4 s before move 2 (which makes no unit), 8 s after the last
    // move (3). Units: two of move 0, one of move 1, one of move 3.
    const std::vector<HostWait> waits = {{0, 1.0, WaitCause::Dwell, 1},
                                         {1, 2.0, WaitCause::Dwell, 2},
                                         {2, 4.0, WaitCause::OperatorPause, 3},
                                         {4, 8.0, WaitCause::OtherAxes, 5}};
    UnitWaitLayer layer(waits);
    EXPECT_DOUBLE_EQ(layer.before_unit(0), 1.0);
    EXPECT_DOUBLE_EQ(layer.before_unit(0), 0.0);  // the move's second unit
    EXPECT_DOUBLE_EQ(layer.before_unit(1), 2.0);
    EXPECT_DOUBLE_EQ(layer.before_unit(3), 4.0);  // move 2's wait passed on
    EXPECT_DOUBLE_EQ(layer.after_last(), 8.0);
}

}  // namespace
}  // namespace cnc::host
