#include "host/core/planner/planner.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/bad_input.hpp"
#include "host/core/planner/corner_blend.hpp"
#include "host/core/planner/lookahead.hpp"
#include "host/core/planner/path_limits.hpp"

namespace cnc::host::planner {

namespace {

// Issue 4: moves shorter than this are skipped (far below one 6.25 um microstep).
constexpr double kMinPieceMm = 1e-9;
// Issue 4: two tangent directions are the same (or opposite) when |u1 x u2| is at most this.
constexpr double kSameDirection = 1e-9;
constexpr double kSecondsPerMinute = 60.0;

struct KeptMove {
    int move;
    Curve curve;
    double feed_mm_per_s;
    double wait_before_s;  // host waits (dwell, pause, Z move) since the kept move before: the tool rests
};

// What happens where kept move j meets kept move j + 1.
struct Join {
    bool stop;
    std::optional<Curve> blend;
};

// A piece being assembled, before its speeds are known.
struct Draft {
    Curve path;
    int move;
    double feed_mm_per_s;
    bool stop_before;
    int last_move_needed;
    double wait_before_s;
};

// Where a move's window comes from: its own piece, or (no piece) the start of piece `piece`.
struct WindowSource {
    std::size_t piece;
    bool own;
};

struct Layout {
    std::vector<Draft> drafts;
    std::vector<WindowSource> windows;
};

double feed_of(const ProgrammedMove& m, const std::string& file) {
    if (!(m.feed_mm_per_min > 0.0)) throw BadInput(file + ":" + std::to_string(m.line), "feed must be > 0");
    return m.feed_mm_per_min / kSecondsPerMinute;
}

std::vector<KeptMove> kept_moves(const Program& program) {
    std::vector<KeptMove> kept;
    std::size_t waits_from = 0;
    for (std::size_t i = 0; i < program.moves.size(); ++i) {
        const ProgrammedMove& m = program.moves[i];
        const double feed = feed_of(m, program.filename);
        const Curve c = Curve::from_segment(m.path);
        if (c.length_mm() >= kMinPieceMm) {
            kept.push_back(KeptMove{static_cast<int>(i), c, feed, program.wait_s_between(waits_from, i + 1)});
            waits_from = i + 1;
        }
    }
    return kept;
}

// The path control in force at the end of a programmed move: the program's G61/G61.1/G64 when it has one,
// the scenario's planner.mode and path_tolerance_mm otherwise. G61.1 (exact path) blends nothing but, unlike
// G61, crosses tangent joins without stopping; G64 without P (or P0) keeps the scenario's tolerance.
std::pair<BlendMode, double> path_control(const ProgrammedMove& m, const PlannerConfig& cfg) {
    if (!m.path_control) return {cfg.mode, cfg.path_tolerance_mm};
    switch (m.path_control->mode) {
        case PathMode::ExactStop: return {BlendMode::ExactStop, 0.0};
        case PathMode::ExactPath: return {BlendMode::Continuous, 0.0};
        case PathMode::Blend: break;
    }
    const double p = m.path_control->tolerance_mm.value_or(0.0);
    return {BlendMode::Continuous, p > 0.0 ? p : cfg.path_tolerance_mm};
}

Join join(const Curve& a, const Curve& b, std::pair<BlendMode, double> control) {
    const auto [mode, tolerance_mm] = control;
    if (mode == BlendMode::ExactStop) return Join{true, std::nullopt};
    const geom::Vec2 u1 = a.unit_tangent_at(a.length_mm());
    const geom::Vec2 u2 = b.unit_tangent_at(0.0);
    if (std::fabs(cross(u1, u2)) <= kSameDirection) return Join{geom::dot(u1, u2) < 0.0, std::nullopt};
    std::optional<Curve> blend = corner_blend(a, b, tolerance_mm);
    return Join{!blend, blend};
}

// The pieces in path order: each kept move cut by the blends at its ends, the blends between them.
Layout lay_out(const std::vector<KeptMove>& kept, const std::vector<Join>& joins, std::size_t n_moves) {
    Layout out;
    out.windows.assign(n_moves, WindowSource{0, false});
    std::size_t next_unassigned = 0;  // moves before a kept one were skipped: empty window where it starts
    bool stop_pending = true;         // the program starts at rest
    for (std::size_t j = 0; j < kept.size(); ++j) {
        const auto move = static_cast<std::size_t>(kept[j].move);
        for (; next_unassigned < move; ++next_unassigned) out.windows[next_unassigned] = {out.drafts.size(), false};
        const std::optional<Curve>& before = j > 0 ? joins[j - 1].blend : std::nullopt;
        const std::optional<Curve>& after = j < joins.size() ? joins[j].blend : std::nullopt;
        Curve c = kept[j].curve;
        if (before) c = c.cut_start(before->end);
        if (after) c = c.cut_end(after->start);
        const bool has_piece = c.length_mm() >= kMinPieceMm;
        out.windows[move] = {out.drafts.size(), has_piece};
        next_unassigned = move + 1;
        if (has_piece) {
            out.drafts.push_back(
                Draft{c, kept[j].move, kept[j].feed_mm_per_s, stop_pending, kept[j].move, kept[j].wait_before_s});
            stop_pending = false;
        }
        if (after) {
            const double feed = std::min(kept[j].feed_mm_per_s, kept[j + 1].feed_mm_per_s);
            out.drafts.push_back(Draft{*after, -1, feed, stop_pending, kept[j + 1].move, 0.0});
            stop_pending = false;
        } else {
            stop_pending = stop_pending || j + 1 == kept.size() || joins[j].stop;
        }
    }
    for (; next_unassigned < n_moves; ++next_unassigned) out.windows[next_unassigned] = {out.drafts.size(), false};
    return out;
}

std::vector<PlannedPiece> schedule(const std::vector<Draft>& drafts, const PlannerConfig& cfg) {
    std::vector<LookaheadPiece> look;
    look.reserve(drafts.size());
    for (std::size_t k = 0; k < drafts.size(); ++k) {
        const PathLimits lim = path_limits(drafts[k].path, drafts[k].feed_mm_per_s, cfg);
        const bool joined = k > 0 && !drafts[k].stop_before;
        const double cap = joined ? std::min(lim.velocity_mm_per_s, look[k - 1].limits.velocity_mm_per_s) : 0.0;
        look.push_back(LookaheadPiece{drafts[k].path.length_mm(), lim, cap, drafts[k].last_move_needed});
    }
    const std::vector<double> speeds = boundary_speeds(look, cfg.profile, cfg.lookahead_moves);
    std::vector<PlannedPiece> pieces;
    pieces.reserve(drafts.size());
    double t = 0.0;
    for (std::size_t k = 0; k < drafts.size(); ++k) {
        const SpeedProfile sp =
            make_speed_profile(cfg.profile, look[k].length_mm, speeds[k], speeds[k + 1], look[k].limits);
        t += drafts[k].wait_before_s;
        pieces.push_back(PlannedPiece{drafts[k].path, drafts[k].move, t, t + sp.duration_s(), sp});
        t = pieces.back().t_end_s;
    }
    return pieces;
}

}  // namespace

Trajectory plan(const Program& program, const PlannerConfig& cfg) {
    validate(cfg, "planner");
    const std::vector<KeptMove> kept = kept_moves(program);
    std::vector<Join> joins;
    for (std::size_t j = 0; j + 1 < kept.size(); ++j) {
        // A host wait between two moves is a rest: the tool stops, waits, starts again.
        joins.push_back(kept[j + 1].wait_before_s > 0.0
                            ? Join{true, std::nullopt}
                            : join(kept[j].curve, kept[j + 1].curve,
                                   path_control(program.moves[static_cast<std::size_t>(kept[j].move)], cfg)));
    }
    const Layout layout = lay_out(kept, joins, program.moves.size());
    std::vector<PlannedPiece> pieces = schedule(layout.drafts, cfg);

    const double end_s = pieces.empty() ? 0.0 : pieces.back().t_end_s;
    std::vector<std::pair<double, double>> windows;
    for (const WindowSource& src : layout.windows) {
        if (src.own) {
            windows.emplace_back(pieces[src.piece].t_begin_s, pieces[src.piece].t_end_s);
        } else {
            const double at = src.piece < pieces.size() ? pieces[src.piece].t_begin_s : end_s;
            windows.emplace_back(at, at);
        }
    }
    geom::Vec2 rest{};
    if (!program.moves.empty()) rest = kept.empty() ? program.moves.front().path.start : kept.front().curve.start;
    const std::size_t after_last = kept.empty() ? 0 : static_cast<std::size_t>(kept.back().move) + 1;
    const double hold_s = program.wait_s_between(kept.empty() ? 0 : after_last, program.moves.size() + 1);
    return Trajectory(std::move(pieces), std::move(windows), rest, hold_s);
}

}  // namespace cnc::host::planner
