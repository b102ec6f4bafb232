#include "host/core/cam.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>

#include "common/bad_input.hpp"
#include "common/math_constants.hpp"

namespace cnc::host {

namespace {

constexpr std::int64_t kInt32Min = -2147483648LL;  // seed 000 §4.8: StepsX/StepsY are int32
constexpr std::int64_t kInt32Max = 2147483647LL;
constexpr double kMaxFeed = 65535.0;  // seed 000 §4.8: FeedRate is uint16, mm/min
// Above 2^53 a double no longer holds every integer, so absolute step positions would stop being exact.
constexpr double kMaxAbsoluteSteps = 9007199254740992.0;
// Guard against a tolerance so small that an arc becomes millions of packets (a sign of a wrong setting).
constexpr std::int64_t kMaxChordsPerArc = 1'000'000;

std::string number_text(double v) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

// Absolute position in steps. Rounding absolute positions (not each displacement, as seed 000 §3.4.3 does, whose
// errors add up) keeps the commanded step position within half a step of the path however many segments there
// are; llround rounds halves away from zero, so a mirrored path gives mirrored steps.
std::int64_t absolute_steps(double pos_mm, double steps_per_mm, const std::string& where, const char* axis) {
    const double steps = pos_mm * steps_per_mm;
    if (!(std::fabs(steps) < kMaxAbsoluteSteps)) {
        throw BadInput(where, std::string(axis) + " position " + number_text(pos_mm) + " mm is beyond 2^53 steps");
    }
    return std::llround(steps);
}

void check_int32(std::int64_t steps, const std::string& where, const char* name) {
    if (steps < kInt32Min || steps > kInt32Max) {
        throw BadInput(where,
                       std::string(name) + " " + std::to_string(steps) + " outside int32 (-2147483648..2147483647)");
    }
}

struct StepPos {
    std::int64_t x = 0;
    std::int64_t y = 0;
};

// The machine's step grid: absolute step positions and machine mm, each axis with its own steps/mm.
struct StepGrid {
    double spm_x;
    double spm_y;

    [[nodiscard]] geom::Vec2 mm(std::int64_t x, std::int64_t y) const {
        return {static_cast<double>(x) / spm_x, static_cast<double>(y) / spm_y};
    }
    [[nodiscard]] StepPos round(geom::Vec2 p, const std::string& where) const {
        return {absolute_steps(p.x_mm, spm_x, where, "X"), absolute_steps(p.y_mm, spm_y, where, "Y")};
    }
};

// Largest angle a chord may span with its sagitta within tolerance_mm.
double max_chord_rad(double radius_mm, double tolerance_mm) {
    // Sagitta of a chord spanning angle a: R (1 - cos(a/2)) <= tol  <=>  a <= 2 acos(1 - tol/R)
    // = 4 asin(sqrt(tol / 2R)) (same value, no cancellation for R >> tol). The sagitta formula holds up to
    // a = pi (sagitta R), so when tol >= R each chord spans at most half a turn.
    return tolerance_mm >= radius_mm ? kPi : 4.0 * std::asin(std::sqrt(tolerance_mm / (2.0 * radius_mm)));
}

// An arc's chording: the inscribed polygon of n chords of equal angle (seed 000 §2.4, §3.4.4).
struct ArcChords {
    geom::Vec2 center;
    double r_mm;
    double a0_rad;     // angle of the start point about the centre
    double sweep_rad;  // signed, as geom::Segment
    std::int64_t n;

    // Angle travelled from the start to ideal end k (0..n), in the arc's direction.
    [[nodiscard]] double ideal_rad(std::int64_t k) const {
        return std::fabs(sweep_rad) * static_cast<double>(k) / static_cast<double>(n);
    }
    [[nodiscard]] geom::Vec2 ideal_end(std::int64_t k) const {
        const double a = a0_rad + sweep_rad * static_cast<double>(k) / static_cast<double>(n);
        return center + geom::Vec2{std::cos(a) * r_mm, std::sin(a) * r_mm};
    }
    // Angle travelled from the start to p, in the arc's direction; of the values 2 pi apart, the one nearest
    // near_rad. NaN for the centre, which has no angle (so it is never "in order").
    [[nodiscard]] double travelled_rad(geom::Vec2 p, double near_rad) const {
        const geom::Vec2 d = p - center;
        if (d.x_mm == 0.0 && d.y_mm == 0.0) return std::nan("");
        const double dir = sweep_rad < 0.0 ? -1.0 : 1.0;
        return near_rad + dir * std::remainder(std::atan2(d.y_mm, d.x_mm) - (a0_rad + dir * near_rad), 2.0 * kPi);
    }
};

// ChordEnds::OnArc. Interior end k is the grid point nearest the circle (smallest |distance to centre - R|, in
// mm, so axes with different steps/mm compare fairly) among the points within +-W steps per axis of the rounded
// ideal end (the four floor/ceil corners round it when W = 0) whose angle lies strictly between the previous
// chosen end and ideal end k+1 (for the last interior end: the rounded programmed end) in the arc's direction,
// so that chords stay in order and none is empty. Ties: nearer the ideal end, then smaller X, then smaller Y.
// Margin. The sagitta of a chord spanning angle a is R (1 - cos(a/2)) ~ R a^2 / 8, so counting chords for
// kOnArcSagittaShare = 0.8 of the tolerance lets a span grow by 1/sqrt(0.8) - 1 = 11.8 % before its sagitta
// reaches the tolerance. Snapping moves an end along the arc by at most its window's reach: the ideal end's
// rounding (<= 0.5 step per axis) plus W <= 5 % of the longest chord's arc length per axis. A chord whose
// tangent runs along an axis thus grows by <= 10 % + 1 step. Along a diagonal the reach is sqrt(2) larger
// (<= 14 % + 1.4 steps), but only if both ends land in opposite window corners; the rounding share is
// Round's too. Measured at R = 10 mm, 160 steps/mm, tol 0.002 mm: the
// longest chord spans 0.956 of the tolerance's span (sagitta 0.91 x tol); at R = 500 mm 0.914.
// W is capped at 3 steps, which already offers ~7 grid points along the arc to choose from.
int window_steps(double longest_chord_mm, double steps_per_mm) {
    return static_cast<int>(std::min(3.0, std::floor(0.05 * longest_chord_mm * steps_per_mm)));
}

// Candidate steps on one axis: the floor and ceiling of the ideal position when w is 0, else the rounded
// position +-w.
std::pair<std::int64_t, std::int64_t> candidate_steps(double pos_mm, double steps_per_mm, std::int64_t rounded, int w) {
    if (w > 0) return {rounded - w, rounded + w};
    const double steps = pos_mm * steps_per_mm;
    return {static_cast<std::int64_t>(std::floor(steps)), static_cast<std::int64_t>(std::ceil(steps))};
}

struct SnappedEnd {
    StepPos pos;
    double travelled_rad;
    double residual_mm;  // |distance to centre - R|
    double offset_mm;    // distance to the ideal end
};

// Residuals or offsets closer than 1 pm count as equal, so that floating-point noise does not decide
// between mirror-image candidates.
constexpr double kTieMm = 1e-9;

// ChordEnds::OnArc: the grid point for interior end k, strictly between after_rad and before_rad in the
// arc's direction. None if no candidate lies there, or if the best one lies further from the circle than the
// rounded ideal end (Round's choice), which happens only where chords are shorter than a step: a worse point
// would zig-zag across the circle, so the end is left out and the next chord carries it.
std::optional<SnappedEnd> snap_end(const ArcChords& arc, std::int64_t k, double after_rad, double before_rad,
                                   const StepGrid& grid, int w_x, int w_y, const std::string& where) {
    const geom::Vec2 ideal = arc.ideal_end(k);
    const StepPos rounded = grid.round(ideal, where);  // also checks the 2^53 range
    const auto [x_lo, x_hi] = candidate_steps(ideal.x_mm, grid.spm_x, rounded.x, w_x);
    const auto [y_lo, y_hi] = candidate_steps(ideal.y_mm, grid.spm_y, rounded.y, w_y);
    std::optional<SnappedEnd> best;
    for (std::int64_t x = x_lo; x <= x_hi; ++x) {
        for (std::int64_t y = y_lo; y <= y_hi; ++y) {
            const geom::Vec2 p = grid.mm(x, y);
            const double travelled = arc.travelled_rad(p, arc.ideal_rad(k));
            if (!(travelled > after_rad && travelled < before_rad)) continue;
            const SnappedEnd c{
                {x, y}, travelled, std::fabs(geom::distance(p, arc.center) - arc.r_mm), geom::distance(p, ideal)};
            const bool better = !best || c.residual_mm < best->residual_mm - kTieMm ||
                                (c.residual_mm <= best->residual_mm + kTieMm && c.offset_mm < best->offset_mm - kTieMm);
            if (better) best = c;  // scanning X then Y upwards: on a full tie the smaller X, then Y, stays
        }
    }
    const double rounded_residual_mm = std::fabs(geom::distance(grid.mm(rounded.x, rounded.y), arc.center) - arc.r_mm);
    if (best && best->residual_mm > rounded_residual_mm + kTieMm) return {};
    return best;
}

// Chord end points of a move in absolute steps, starting from the machine's position `from`; the last is the
// programmed end point. A line is one "chord".
std::vector<StepPos> chord_ends(const geom::Segment& path, StepPos from, const StepGrid& grid, const CamOptions& opt,
                                const std::string& where) {
    const StepPos end = grid.round(path.end, where);
    if (!path.is_arc) return {end};
    const bool on_arc = opt.chord_ends == ChordEnds::OnArc;
    const double count_tolerance_mm = on_arc ? kOnArcSagittaShare * opt.chord_tolerance_mm : opt.chord_tolerance_mm;
    const ArcChords arc{path.center, path.radius_mm(),
                        std::atan2(path.start.y_mm - path.center.y_mm, path.start.x_mm - path.center.x_mm),
                        path.sweep_rad, chord_count(path.radius_mm(), path.sweep_rad, count_tolerance_mm)};
    if (arc.n > kMaxChordsPerArc) {
        throw BadInput(where, "arc needs " + std::to_string(arc.n) + " chords at a chord tolerance of " +
                                  number_text(opt.chord_tolerance_mm) + " mm (at most 1000000)");
    }
    std::vector<StepPos> ends;
    ends.reserve(static_cast<std::size_t>(arc.n));
    if (!on_arc) {
        for (std::int64_t k = 1; k < arc.n; ++k) ends.push_back(grid.round(arc.ideal_end(k), where));
        ends.push_back(end);
        return ends;
    }
    const double longest_chord_mm = max_chord_rad(arc.r_mm, count_tolerance_mm) * arc.r_mm;
    const int w_x = window_steps(longest_chord_mm, grid.spm_x);
    const int w_y = window_steps(longest_chord_mm, grid.spm_y);
    const double start_rad = arc.travelled_rad(grid.mm(from.x, from.y), 0.0);
    double after_rad = std::isnan(start_rad) ? 0.0 : start_rad;
    // The end point is fixed, so the last interior end must come before it, not before the ideal end.
    const double end_rad = arc.travelled_rad(grid.mm(end.x, end.y), arc.ideal_rad(arc.n));
    for (std::int64_t k = 1; k < arc.n; ++k) {
        const double before_rad = k + 1 < arc.n ? arc.ideal_rad(k + 1) : end_rad;
        if (const auto s = snap_end(arc, k, after_rad, before_rad, grid, w_x, w_y, where)) {
            ends.push_back(s->pos);
            after_rad = s->travelled_rad;
        }
    }
    ends.push_back(end);
    return ends;
}

// seed 000 §3.4.5 "NUMERATOR concept": F is the path speed; the packet carries the dominant axis' share
// axisFeed = F x dominant_distance / path_length. The distances are the step-quantised ones (steps / steps_per_mm),
// i.e. what the machine really moves, so the executed path speed is F even when rounding bent the segment.
// The dominant axis is the one with more steps, X on a tie, as step_gen decides (seed 000 §5.2.4).
// A path feed that would drive an axis past machine.<axis>.max_velocity_mm_per_s is lowered to that limit first.
std::int64_t packet_feed(const ProgrammedMove& move, const MotionSegment& seg, const MachineModel& machine,
                         const CamOptions& opt, const std::string& where) {
    const double path_feed = feed_within_axis_limits(seg.dx_mm, seg.dy_mm, move.feed_mm_per_min, machine);
    double axis_feed = path_feed;
    if (move.kind != MotionKind::Rapid || opt.correct_rapid_feed) {
        const bool x_dominant = std::llabs(seg.steps_x) >= std::llabs(seg.steps_y);
        const double dominant_mm = std::fabs(x_dominant ? seg.dx_mm : seg.dy_mm);
        axis_feed = path_feed * dominant_mm / std::hypot(seg.dx_mm, seg.dy_mm);
    }
    const double feed = opt.feed_rounding == FeedRounding::Round ? std::round(axis_feed) : std::floor(axis_feed);
    if (feed < 1.0) {
        throw BadInput(
            where, "feed " + number_text(axis_feed) + " mm/min rounds to 0 (packet FeedRate must be 1..65535 mm/min)");
    }
    if (feed > kMaxFeed) {
        throw BadInput(where,
                       "feed " + number_text(feed) + " mm/min outside the packet FeedRate range 1..65535 mm/min");
    }
    return static_cast<std::int64_t>(feed);
}

}  // namespace

std::int64_t chord_count(double radius_mm, double sweep_rad, double tolerance_mm) {
    const double n = std::ceil(std::fabs(sweep_rad) / max_chord_rad(radius_mm, tolerance_mm));
    return n < 1.0 ? 1 : (n > 9.0e18 ? INT64_MAX : static_cast<std::int64_t>(n));
}

CamStream::CamStream(std::string filename, const MachineModel& machine, const CamOptions& opt)
    : m_file(std::move(filename)), m_machine(machine), m_opt(opt) {
    validate(machine, "machine");
    if (!(std::isfinite(opt.chord_tolerance_mm) && opt.chord_tolerance_mm > 0.0)) {
        throw BadInput("cam", "chord_tolerance_mm must be > 0");
    }
}

void CamStream::add(const ProgrammedMove& move, std::size_t m, std::vector<MotionSegment>& out) {
    const StepGrid grid{m_machine.x.steps_per_mm(), m_machine.y.steps_per_mm()};
    const std::string where = m_file + ":" + std::to_string(move.line);
    if (!m_started) {
        const StepPos start = grid.round(move.path.start, where);
        m_at_x = start.x;
        m_at_y = start.y;
        m_started = true;
    }
    StepPos cur{m_at_x, m_at_y};
    for (const StepPos& p : chord_ends(move.path, cur, grid, m_opt, where)) {
        MotionSegment seg;
        seg.steps_x = p.x - cur.x;
        seg.steps_y = p.y - cur.y;
        if (seg.steps_x == 0 && seg.steps_y == 0) continue;  // the next chord carries the remainder
        check_int32(seg.steps_x, where, "steps_x");
        check_int32(seg.steps_y, where, "steps_y");
        seg.index = static_cast<int>(++m_segments);
        seg.motion = move.kind;
        seg.path_feed_mm_per_min = move.feed_mm_per_min;
        seg.move = static_cast<int>(m);
        seg.line = move.line;
        seg.dx_mm = static_cast<double>(seg.steps_x) / grid.spm_x;
        seg.dy_mm = static_cast<double>(seg.steps_y) / grid.spm_y;
        seg.feed = packet_feed(move, seg, m_machine, m_opt, where);
        out.push_back(seg);
        cur = p;
    }
    m_at_x = cur.x;
    m_at_y = cur.y;
}

std::vector<MotionSegment> cam(const Program& program, const MachineModel& machine, const CamOptions& opt) {
    CamStream stream(program.filename, machine, opt);
    std::vector<MotionSegment> segments;
    for (std::size_t m = 0; m < program.moves.size(); ++m) stream.add(program.moves[m], m, segments);
    return segments;
}

std::uint32_t numerator(double steps_per_mm, std::uint32_t clk_hz) {
    if (!(std::isfinite(steps_per_mm) && steps_per_mm > 0.0)) {
        throw BadInput("machine", "steps_per_mm must be > 0 for NUMERATOR");
    }
    const double n = std::round(static_cast<double>(clk_hz) * 60.0 / steps_per_mm);
    if (n < 1.0 || n > 4294967295.0) {  // seed 000 §4.8: NUMERATOR is uint32, 1..4,294,967,295
        throw BadInput("machine", "NUMERATOR = clk_hz x 60 / steps_per_mm = " + number_text(n) +
                                      " does not fit uint32 (1..4294967295)");
    }
    return static_cast<std::uint32_t>(n);
}

}  // namespace cnc::host
