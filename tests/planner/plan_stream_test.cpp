// Planning a job a move at a time (plan_stream.hpp) must give the whole program's plan exactly: the same pieces,
// profiles, times and move windows, bit for bit, so that a streamed spi-fpga run reports what a whole one does.
#include <algorithm>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "host/core/planner/plan_stream.hpp"
#include "planner_test_util.hpp"

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

}  // namespace
}  // namespace cnc::host::planner
