#include "host/core/planner/plan_stream.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "common/bad_input.hpp"
#include "host/core/planner/corner_blend.hpp"
#include "host/core/planner/path_limits.hpp"
#include "host/core/planner/speed_profile.hpp"

namespace cnc::host::planner {

namespace {

// Moves shorter than this are skipped (far below one 6.25 um microstep).
constexpr double kMinPieceMm = 1e-9;
// Two tangent directions are the same (or opposite) when |u1 x u2| is at most this.
constexpr double kSameDirection = 1e-9;
constexpr double kSecondsPerMinute = 60.0;
// LinuxCNC tc.c tcFindBlendTolerance: a blend stays within a quarter of each move's nominal length of the corner.
constexpr double kQuarter = 0.25;
// LinuxCNC's ARC_BLEND_KINK_RATIO default (ini/initraj.cc): the acceleration a kink may take from a move.
constexpr double kKinkRatio = 0.1;
// LinuxCNC tc.c tcGetOverallMaxAccel: a segment whose end condition is still a parabolic blend (G64 with nothing
// queued after it: the program's last move, or the last before a host wait) gets half the acceleration.
constexpr double kParabolicEndAccelScale = 0.5;

// What happens where one kept move meets the next.
struct Join {
    bool stop;
    std::optional<Curve> blend;
    // LinuxCNC tc.c tcGetOverallMaxAccel, tp.c tpChooseBestBlend: a corner stopped at in G61 keeps the
    // acceleration reduction of the kink test (ARC_BLEND_KINK_RATIO, 0.1) on both its moves.
    bool kink = false;
};

double feed_of(const ProgrammedMove& m, const std::string& file) {
    if (!(m.feed_mm_per_min > 0.0)) throw BadInput(file + ":" + std::to_string(m.line), "feed must be > 0");
    return m.feed_mm_per_min / kSecondsPerMinute;
}

// The program's G61/G61.1/G64 when it has set one, the scenario's planner.mode and path_tolerance_mm until then.
// G64 without P (or P0) sets no tolerance: LinuxCNC then rounds a corner as far as the moves' lengths allow.
JoinControl path_control(const ProgrammedMove& m, const PlannerConfig& cfg) {
    if (!m.path_control) return {cfg.mode, cfg.path_tolerance_mm};
    switch (m.path_control->mode) {
        case PathMode::ExactStop:
            return {BlendMode::ExactStop, std::nullopt};
        case PathMode::ExactPath:
            return {BlendMode::ExactPath, std::nullopt};
        case PathMode::Blend:
            break;
    }
    const double p = m.path_control->tolerance_mm.value_or(0.0);
    return {BlendMode::Continuous, p > 0.0 ? std::optional(p) : std::nullopt};
}

// LinuxCNC 2.9's trajectory planner (src/emc/tp/tp.c) at a join: G61.1 stops; so does a change between rapid and
// feed motion (handleModeChange: "can't blend between rapid and feed motions") and a reversal; tangent joins are
// crossed; G61 stops at any other corner, G64 rounds it by an arc (corner_blend.hpp) within the tolerance and a
// quarter of each move's length (tc.c tcFindBlendTolerance), or stops where none fits.
Join join(const PlanStream::KeptMove& a, const PlanStream::KeptMove& b, const PlannerConfig& cfg) {
    if (a.control.mode == BlendMode::ExactStop || a.rapid != b.rapid) return Join{true, std::nullopt};
    const geom::Vec2 u1 = a.curve.unit_tangent_at(a.curve.length_mm());
    const geom::Vec2 u2 = b.curve.unit_tangent_at(0.0);
    if (std::fabs(cross(u1, u2)) <= kSameDirection) return Join{geom::dot(u1, u2) < 0.0, std::nullopt};
    if (a.control.mode == BlendMode::ExactPath) return Join{true, std::nullopt, true};
    double tolerance_mm = kQuarter * std::min(a.curve.length_mm(), b.curve.length_mm());
    if (a.control.tolerance_mm) tolerance_mm = std::min(tolerance_mm, *a.control.tolerance_mm);
    // blendmath.c blendParamKinematics: the goal is the faster move's feed, within the plane's speed and
    // acceleration (the largest circle inside the axes' limits).
    const double plane_speed = std::min(cfg.x.max_velocity_mm_per_s, cfg.y.max_velocity_mm_per_s);
    const double plane_accel = std::min(cfg.x.max_accel_mm_per_s2, cfg.y.max_accel_mm_per_s2);
    const double goal = std::min(std::max(a.feed_mm_per_s, b.feed_mm_per_s), plane_speed);
    std::optional<Curve> blend = corner_blend(a.curve, b.curve, tolerance_mm, goal, plane_accel);
    return Join{!blend, blend};
}

}  // namespace

PlanStream::PlanStream(const PlannerConfig& cfg, std::string filename)
    : m_cfg(cfg), m_filename(std::move(filename)), m_look(cfg.profile, cfg.lookahead_moves) {
    validate(cfg, "planner");
}

void PlanStream::add_move(const ProgrammedMove& move) {
    const int index = m_moves_read++;
    if (!m_first_start_mm) m_first_start_mm = move.path.start;
    const double feed = feed_of(move, m_filename);
    const Curve c = Curve::from_segment(move.path);
    if (c.length_mm() < kMinPieceMm) return;
    KeptMove kept{
        index, c, feed, std::exchange(m_waits_s, 0.0), move.kind == MotionKind::Rapid, path_control(move, m_cfg)};
    if (!m_first_kept_start_mm) m_first_kept_start_mm = c.start;
    if (m_last_kept) {
        // A host wait between two moves is a rest: the tool stops, waits, starts again.
        const Join j = kept.wait_before_s > 0.0 ? Join{true, std::nullopt} : join(*m_last_kept, kept, m_cfg);
        m_last_kept->kink_after = j.kink;
        kept.kink_before = j.kink;
        lay_out(*m_last_kept, j.blend, j.stop, &kept);
        m_blend_before = j.blend;
    }
    m_last_kept = std::move(kept);
}

void PlanStream::finish() {
    if (m_last_kept) lay_out(*m_last_kept, std::nullopt, true, nullptr);
    for (; m_next_unassigned < m_moves_read; ++m_next_unassigned) m_sources.push_back({m_drafts, false});
    m_finished = true;
    schedule(true);
    for (; !m_sources.empty(); m_sources.pop_front()) m_windows.emplace_back(m_t_s, m_t_s);
    m_end_hold_s = m_waits_s;
}

// The kept move cut by the blends at its ends, then the blend after it (to `next`).
void PlanStream::lay_out(const KeptMove& kept, const std::optional<Curve>& after, bool stop_after,
                         const KeptMove* next) {
    for (; m_next_unassigned < kept.move; ++m_next_unassigned) m_sources.push_back({m_drafts, false});
    Curve c = kept.curve;
    if (m_blend_before) c = c.cut_start(m_blend_before->end);
    if (after) c = c.cut_end(after->start);
    const bool has_piece = c.length_mm() >= kMinPieceMm;
    m_sources.push_back({m_drafts, has_piece});
    m_next_unassigned = kept.move + 1;
    if (has_piece) {
        const bool queue_end = next == nullptr || next->wait_before_s > 0.0;
        double scale = queue_end && kept.control.mode == BlendMode::Continuous ? kParabolicEndAccelScale : 1.0;
        if (kept.kink_before || kept.kink_after) scale *= 1.0 - kKinkRatio;
        add_draft(Draft{c, kept.move, kept.feed_mm_per_s, kept.wait_before_s, {}}, m_stop_pending, kept.move,
                  !queue_end, scale);
        m_stop_pending = false;
    }
    if (after) {
        // LinuxCNC blendmath.c blendParamKinematics: the blend's goal speed is the higher of both moves' feeds.
        const double feed = std::max(kept.feed_mm_per_s, next->feed_mm_per_s);
        add_draft(Draft{*after, -1, feed, 0.0, {}}, m_stop_pending, next->move, false, 1.0);
        m_stop_pending = false;
    } else {
        m_stop_pending = m_stop_pending || stop_after;
    }
}

void PlanStream::add_draft(Draft d, bool stop_before, int last_move_needed, bool finalized, double accel_scale) {
    d.limits = path_limits(d.path, d.feed_mm_per_s, m_cfg, finalized);
    d.limits.accel_mm_per_s2 *= accel_scale;
    const bool joined = m_prev_velocity_mm_per_s && !stop_before;
    const double cap = joined ? std::min(d.limits.velocity_mm_per_s, *m_prev_velocity_mm_per_s) : 0.0;
    m_prev_velocity_mm_per_s = d.limits.velocity_mm_per_s;
    m_look.add(LookaheadPiece{d.path.length_mm(), d.limits, cap, last_move_needed});
    m_unscheduled.push_back(std::move(d));
    ++m_drafts;
}

std::vector<PlannedPiece> PlanStream::take_pieces() {
    schedule(m_finished);
    return std::exchange(m_pieces, {});
}

std::vector<std::pair<double, double>> PlanStream::take_windows() {
    schedule(m_finished);
    return std::exchange(m_windows, {});
}

void PlanStream::schedule(bool ended) {
    while (const std::optional<double> exit = m_look.next_exit(ended)) {
        const Draft& d = m_unscheduled.front();
        const SpeedProfile sp =
            make_speed_profile(m_cfg.profile, d.path.length_mm(), m_entry_mm_per_s, *exit, d.limits);
        m_t_s += d.wait_before_s;
        const PlannedPiece piece{d.path, d.move, m_t_s, m_t_s + sp.duration_s(), sp};
        m_t_s = piece.t_end_s;
        m_entry_mm_per_s = *exit;
        for (; !m_sources.empty() && m_sources.front().piece == m_scheduled; m_sources.pop_front()) {
            m_windows.emplace_back(piece.t_begin_s, m_sources.front().own ? piece.t_end_s : piece.t_begin_s);
        }
        m_pieces.push_back(piece);
        m_unscheduled.pop_front();
        ++m_scheduled;
    }
}

}  // namespace cnc::host::planner
