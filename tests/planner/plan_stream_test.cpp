// Planning a job a move at a time (plan_stream.hpp), and reading it as far as it is asked for (plan_feed.hpp), must
// give the whole program's plan exactly: the same pieces, profiles, times and move windows, bit for bit, so that a
// streamed spi-fpga run reports what a whole one does.
#include <algorithm>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "host/core/planner/plan_feed.hpp"
#include "host/core/planner/plan_stream.hpp"
#include "planner_test_util.hpp"
#include "support/fed_job.hpp"

namespace cnc::host::planner {
namespace {

using test::config;
using test::gcode;

// Short continuous moves (a zigzag of 1 mm steps blended within G64 P), tangent and non-tangent arcs, a reversal,
// a G61 exact-stop stretch, a dwell, a move shorter than 1e-9 mm (skipped), a long move and a wait after the end.
std::string mixed_job() {
    std::string g = "G21 G90 G64 P0.02\nG0 X0 Y0\nG1 F3000\n";
    for (int i = 1; i <= 40; ++i) g += "G1 X" + std::to_string(i) + " Y" + std::to_string(i % 2) + "\n";
    g += "G2 X50 Y0 I5 J0\nG3 X60 Y0 I5 J0\nG1 X70 Y3\nG1 X65 Y3\n";  // arcs, a corner, a reversal
    g += "G61\nG1 X65 Y10\nG1 X70 Y10\nG1 X70 Y15\nG64 P0.02\n";
    g += "G1 X71 Y15\nG4 P0.25\nG1 X72 Y16\nG1 X72 Y16.0000000000001\n";
    for (int i = 1; i <= 20; ++i) g += "G1 X" + std::to_string(72 + i) + " Y" + std::to_string(16 + i % 2) + "\n";
    g += "G0 X200 Y100\nG1 X0 Y0 F6000\nG4 P0.5\n";
    return g;
}

void expect_same(const std::vector<PlannedPiece>& got, const std::vector<PlannedPiece>& want) {
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t k = 0; k < got.size(); ++k) {
        SCOPED_TRACE("piece " + std::to_string(k));
        EXPECT_EQ(got[k].move, want[k].move);
        EXPECT_EQ(got[k].t_begin_s, want[k].t_begin_s);
        EXPECT_EQ(got[k].t_end_s, want[k].t_end_s);
        EXPECT_EQ(got[k].path.start.x_mm, want[k].path.start.x_mm);
        EXPECT_EQ(got[k].path.start.y_mm, want[k].path.start.y_mm);
        EXPECT_EQ(got[k].path.end.x_mm, want[k].path.end.x_mm);
        EXPECT_EQ(got[k].path.end.y_mm, want[k].path.end.y_mm);
        EXPECT_EQ(got[k].path.is_arc, want[k].path.is_arc);
        EXPECT_EQ(got[k].speed.length_mm, want[k].speed.length_mm);
        EXPECT_EQ(got[k].speed.entry_mm_per_s, want[k].speed.entry_mm_per_s);
        EXPECT_EQ(got[k].speed.peak_mm_per_s, want[k].speed.peak_mm_per_s);
        EXPECT_EQ(got[k].speed.exit_mm_per_s, want[k].speed.exit_mm_per_s);
        EXPECT_EQ(got[k].speed.rise_s, want[k].speed.rise_s);
        EXPECT_EQ(got[k].speed.cruise_s, want[k].speed.cruise_s);
        EXPECT_EQ(got[k].speed.fall_s, want[k].speed.fall_s);
    }
}

// The host waits before move i, then move i, for every move; the waits after the last move; then the end.
void feed(PlanStream& stream, const Program& program, const std::function<void(std::size_t)>& after_move) {
    std::size_t w = 0;
    for (std::size_t i = 0; i < program.moves.size(); ++i) {
        for (; w < program.waits.size() && program.waits[w].before_move <= i; ++w) {
            stream.add_wait(program.waits[w].seconds);
        }
        stream.add_move(program.moves[i]);
        after_move(i);
    }
    for (; w < program.waits.size(); ++w) stream.add_wait(program.waits[w].seconds);
    stream.finish();
}

void chunked_equals_whole(const PlannerConfig& cfg) {
    const Program program = gcode(mixed_job(), test::kRapidAboveTheAxes_mm_per_min);
    // The whole program read before anything is planned: one look-ahead pass over every piece.
    PlanStream whole_stream(cfg, program.filename);
    feed(whole_stream, program, [](std::size_t) {});
    const Trajectory whole(whole_stream.take_pieces(), whole_stream.take_windows(), whole_stream.rest_mm(),
                           whole_stream.end_hold_s());

    PlanStream stream(cfg, program.filename);
    std::vector<PlannedPiece> pieces;
    std::vector<std::pair<double, double>> windows;
    std::size_t most_moves_ahead = 0;  // moves read past the last one whose window is known
    feed(stream, program, [&](std::size_t i) {
        for (PlannedPiece& p : stream.take_pieces()) pieces.push_back(std::move(p));
        for (const auto& win : stream.take_windows()) windows.push_back(win);
        most_moves_ahead = std::max(most_moves_ahead, i + 1 - windows.size());
    });
    for (PlannedPiece& p : stream.take_pieces()) pieces.push_back(std::move(p));
    for (const auto& win : stream.take_windows()) windows.push_back(win);

    expect_same(pieces, whole.pieces());
    EXPECT_EQ(windows, whole.move_windows());
    const Trajectory rebuilt(pieces, windows, stream.rest_mm(), stream.end_hold_s());
    EXPECT_EQ(rebuilt.duration_s(), whole.duration_s());
    EXPECT_EQ(stream.end_hold_s(), 0.5);  // the G4 P0.5 after the last move
    // Planned in chunks, not at the end: a piece is final once its window (lookahead_moves moves from its own, plus
    // the one that closes it and the move whose blend may cut it) has been read.
    EXPECT_LE(most_moves_ahead, static_cast<std::size_t>(cfg.lookahead_moves) + 2);
    EXPECT_GT(program.moves.size(), static_cast<std::size_t>(cfg.lookahead_moves) + 2);
    // plan() takes the pieces move by move too.
    expect_same(plan(program, cfg).pieces(), whole.pieces());
}

TEST(PlanStream, ChunkByChunkEqualsTheWholeProgramTrapezoidal) {
    PlannerConfig cfg = config(BlendMode::Continuous);
    cfg.lookahead_moves = 4;
    chunked_equals_whole(cfg);
}

TEST(PlanStream, ChunkByChunkEqualsTheWholeProgramJerkLimited) {
    chunked_equals_whole(config(BlendMode::Continuous, Profile::JerkLimited));
}

TEST(PlanStream, ChunkByChunkEqualsTheWholeProgramExactStop) {
    PlannerConfig cfg = config(BlendMode::ExactStop);
    cfg.lookahead_moves = 1;
    chunked_equals_whole(cfg);
}

// The planned peak path speed of programmed move i: the fastest of its pieces in the whole plan (0 without one).
double peak_of(const Trajectory& whole, std::size_t i) {
    double peak = 0.0;
    for (const PlannedPiece& p : whole.pieces()) {
        if (p.move == static_cast<int>(i)) peak = std::max(peak, p.speed.peak_mm_per_s);
    }
    return peak;
}

// A reader walking through the job (every 1 ms and at every piece boundary), dropping the pieces and the moves
// behind it, reads the whole program's state at every time, and each move's window and peak speed once the walk
// has left the window; the feed holds no more than the look-ahead's pieces around the walk.
void fed_equals_whole(const PlannerConfig& cfg) {
    InterpreterOptions opt;
    opt.rapid_feed_mm_per_min = test::kRapidAboveTheAxes_mm_per_min;
    const Program program = gcode(mixed_job(), opt.rapid_feed_mm_per_min);
    const Trajectory whole = plan(program, cfg);
    cnc::test::FedJob fed(mixed_job(), cfg, opt);

    std::vector<double> times;
    for (double t = 0.0; t < whole.duration_s(); t += 1e-3) times.push_back(t);
    for (const PlannedPiece& p : whole.pieces()) {
        times.push_back(p.t_begin_s);
        times.push_back(p.t_end_s);
    }
    times.push_back(whole.duration_s());
    std::sort(times.begin(), times.end());

    std::size_t next_move = 0;
    std::size_t most_pieces = 0;
    for (const double t : times) {
        SCOPED_TRACE("t = " + std::to_string(t));
        const Sample got = fed.plan.at(t);
        const Sample want = whole.at(t);
        EXPECT_EQ(got.pos_mm.x_mm, want.pos_mm.x_mm);
        EXPECT_EQ(got.pos_mm.y_mm, want.pos_mm.y_mm);
        EXPECT_EQ(got.vel_mm_per_s.x_mm, want.vel_mm_per_s.x_mm);
        EXPECT_EQ(got.vel_mm_per_s.y_mm, want.vel_mm_per_s.y_mm);
        EXPECT_EQ(got.acc_mm_per_s2.x_mm, want.acc_mm_per_s2.x_mm);
        EXPECT_EQ(got.acc_mm_per_s2.y_mm, want.acc_mm_per_s2.y_mm);
        EXPECT_EQ(got.path_speed_mm_per_s, want.path_speed_mm_per_s);
        EXPECT_EQ(got.move, want.move);
        for (; next_move < program.moves.size() && whole.move_windows()[next_move].second < t; ++next_move) {
            const FedMove* m = fed.plan.move(next_move);
            ASSERT_NE(m, nullptr);
            EXPECT_EQ(m->window, whole.move_windows()[next_move]);
            EXPECT_EQ(m->peak_mm_per_s, peak_of(whole, next_move));
            EXPECT_EQ(m->move.line, program.moves[next_move].line);
            fed.plan.drop_moves_before(next_move + 1);
        }
        fed.plan.drop_before(t);
        most_pieces = std::max(most_pieces, fed.plan.trajectory().pieces().size());
    }
    EXPECT_TRUE(fed.plan.complete());
    EXPECT_EQ(fed.plan.trajectory().duration_s(), whole.duration_s());
    EXPECT_EQ(next_move, program.moves.size());
    EXPECT_EQ(fed.plan.move(program.moves.size()), nullptr);
    // Each move gives at most two pieces (its own and the blend after it); a piece is final once its look-ahead
    // window and two moves more are read (the stream's test above).
    EXPECT_LE(most_pieces, 2 * (static_cast<std::size_t>(cfg.lookahead_moves) + 3));
    EXPECT_LT(most_pieces, whole.pieces().size() / 4);
}

TEST(PlanFeed, ReadAsFarAsAskedEqualsTheWholeProgramTrapezoidal) {
    PlannerConfig cfg = config(BlendMode::Continuous);
    cfg.lookahead_moves = 4;
    fed_equals_whole(cfg);
}

TEST(PlanFeed, ReadAsFarAsAskedEqualsTheWholeProgramJerkLimited) {
    PlannerConfig cfg = config(BlendMode::Continuous, Profile::JerkLimited);
    cfg.lookahead_moves = 6;  // the job is a few windows long
    fed_equals_whole(cfg);
}

TEST(PlanFeed, ReadAsFarAsAskedEqualsTheWholeProgramExactStop) {
    PlannerConfig cfg = config(BlendMode::ExactStop);
    cfg.lookahead_moves = 1;
    fed_equals_whole(cfg);
}

}  // namespace
}  // namespace cnc::host::planner
