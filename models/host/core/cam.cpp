#include "host/core/cam.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "common/bad_input.hpp"

namespace cnc::host {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr std::int64_t kInt32Min = -2147483648LL;  // seed 000 §3.4.6: StepsX/StepsY are int32
constexpr std::int64_t kInt32Max = 2147483647LL;
constexpr double kMaxFeed = 65535.0;               // seed 000 §3.4.6: FeedRate is uint16, mm/min
// Above 2^53 a double no longer holds every integer, so absolute step positions would stop being exact.
constexpr double kMaxAbsoluteSteps = 9007199254740992.0;
// Guard against a tolerance so small that an arc becomes millions of packets (a sign of a wrong setting).
constexpr std::int64_t kMaxChordsPerArc = 1'000'000;

std::string number_text(double v) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

// Absolute position in steps. Rounding absolute positions (not each displacement) keeps the commanded step
// position within half a step of the path however many segments there are (seed 000 Q11); llround rounds
// halves away from zero, so a mirrored path gives mirrored steps.
std::int64_t absolute_steps(double pos_mm, double steps_per_mm, const std::string& where, const char* axis) {
    const double steps = pos_mm * steps_per_mm;
    if (!(std::fabs(steps) < kMaxAbsoluteSteps)) {
        throw BadInput(where, std::string(axis) + " position " + number_text(pos_mm) + " mm is beyond 2^53 steps");
    }
    return std::llround(steps);
}

void check_int32(std::int64_t steps, const std::string& where, const char* name) {
    if (steps < kInt32Min || steps > kInt32Max) {
        throw BadInput(where, std::string(name) + " " + std::to_string(steps) +
                                  " outside int32 (-2147483648..2147483647)");
    }
}

// Chord end points of an arc, ON the arc; the last is the programmed end point. A line is one "chord".
std::vector<geom::Vec2> chord_ends(const geom::Segment& path, double tolerance_mm, const std::string& where) {
    if (!path.is_arc) return {path.end};
    const std::int64_t n = chord_count(path.radius_mm(), path.sweep_rad, tolerance_mm);
    if (n > kMaxChordsPerArc) {
        throw BadInput(where, "arc needs " + std::to_string(n) + " chords at a chord tolerance of " +
                                  number_text(tolerance_mm) + " mm (at most 1000000)");
    }
    const double r = path.radius_mm();
    const double a0 = std::atan2(path.start.y_mm - path.center.y_mm, path.start.x_mm - path.center.x_mm);
    std::vector<geom::Vec2> ends;
    ends.reserve(static_cast<std::size_t>(n));
    for (std::int64_t k = 1; k < n; ++k) {
        const double a = a0 + path.sweep_rad * static_cast<double>(k) / static_cast<double>(n);
        ends.push_back(path.center + geom::Vec2{std::cos(a) * r, std::sin(a) * r});
    }
    ends.push_back(path.end);
    return ends;
}

// seed 000 §3.4.5 "NUMERATOR concept": F is the path speed; the packet carries the dominant axis' share
// axisFeed = F x dominant_distance / path_length. The distances are the step-quantised ones (steps / steps_per_mm),
// i.e. what the machine really moves, so the executed path speed is F even when rounding bent the segment.
// The dominant axis is the one with more steps, X on a tie, as step_gen decides (seed 000 §5.4).
std::int64_t packet_feed(const ProgrammedMove& move, const MotionSegment& seg, const CamOptions& opt,
                         const std::string& where) {
    double axis_feed = move.feed_mm_per_min;
    if (move.kind != MotionKind::Rapid || opt.correct_rapid_feed) {
        const bool x_dominant = std::llabs(seg.steps_x) >= std::llabs(seg.steps_y);
        const double dominant_mm = std::fabs(x_dominant ? seg.dx_mm : seg.dy_mm);
        axis_feed = move.feed_mm_per_min * dominant_mm / std::hypot(seg.dx_mm, seg.dy_mm);
    }
    const double feed = opt.feed_rounding == FeedRounding::Round ? std::round(axis_feed) : std::floor(axis_feed);
    if (feed < 1.0) {
        throw BadInput(where, "feed " + number_text(axis_feed) +
                                  " mm/min rounds to 0 (packet FeedRate must be 1..65535 mm/min)");
    }
    if (feed > kMaxFeed) {
        throw BadInput(where, "feed " + number_text(feed) + " mm/min outside the packet FeedRate range 1..65535 mm/min");
    }
    return static_cast<std::int64_t>(feed);
}

}  // namespace

std::int64_t chord_count(double radius_mm, double sweep_rad, double tolerance_mm) {
    // Sagitta of a chord spanning angle a: R (1 - cos(a/2)) <= tol  <=>  a <= 2 acos(1 - tol/R)
    // = 4 asin(sqrt(tol / 2R)) (same value, no cancellation for R >> tol). The sagitta formula holds up to
    // a = pi (sagitta R), so when tol >= R each chord spans at most half a turn.
    const double max_chord_rad = tolerance_mm >= radius_mm ? kPi : 4.0 * std::asin(std::sqrt(tolerance_mm / (2.0 * radius_mm)));
    const double n = std::ceil(std::fabs(sweep_rad) / max_chord_rad);
    return n < 1.0 ? 1 : (n > 9.0e18 ? INT64_MAX : static_cast<std::int64_t>(n));
}

std::vector<MotionSegment> cam(const Program& program, const MachineModel& machine, const CamOptions& opt) {
    validate(machine, "machine");
    if (!(std::isfinite(opt.chord_tolerance_mm) && opt.chord_tolerance_mm > 0.0)) {
        throw BadInput("cam", "chord_tolerance_mm must be > 0");
    }
    const double spm_x = machine.x.steps_per_mm();
    const double spm_y = machine.y.steps_per_mm();
    std::vector<MotionSegment> segments;
    if (program.moves.empty()) return segments;

    const std::string file_where = program.filename + ":" + std::to_string(program.moves.front().line);
    std::int64_t cur_x = absolute_steps(program.moves.front().path.start.x_mm, spm_x, file_where, "X");
    std::int64_t cur_y = absolute_steps(program.moves.front().path.start.y_mm, spm_y, file_where, "Y");
    for (std::size_t m = 0; m < program.moves.size(); ++m) {
        const ProgrammedMove& move = program.moves[m];
        const std::string where = program.filename + ":" + std::to_string(move.line);
        for (const geom::Vec2& p : chord_ends(move.path, opt.chord_tolerance_mm, where)) {
            const std::int64_t x = absolute_steps(p.x_mm, spm_x, where, "X");
            const std::int64_t y = absolute_steps(p.y_mm, spm_y, where, "Y");
            MotionSegment seg;
            seg.steps_x = x - cur_x;
            seg.steps_y = y - cur_y;
            if (seg.steps_x == 0 && seg.steps_y == 0) continue;  // the next chord carries the remainder
            check_int32(seg.steps_x, where, "steps_x");
            check_int32(seg.steps_y, where, "steps_y");
            seg.index = static_cast<int>(segments.size()) + 1;
            seg.motion = move.kind;
            seg.path_feed_mm_per_min = move.feed_mm_per_min;
            seg.move = static_cast<int>(m);
            seg.line = move.line;
            seg.dx_mm = static_cast<double>(seg.steps_x) / spm_x;
            seg.dy_mm = static_cast<double>(seg.steps_y) / spm_y;
            seg.feed = packet_feed(move, seg, opt, where);
            segments.push_back(seg);
            cur_x = x;
            cur_y = y;
        }
    }
    return segments;
}

std::uint32_t numerator(double steps_per_mm, std::uint32_t clk_hz) {
    if (!(std::isfinite(steps_per_mm) && steps_per_mm > 0.0)) {
        throw BadInput("machine", "steps_per_mm must be > 0 for NUMERATOR");
    }
    const double n = std::round(static_cast<double>(clk_hz) * 60.0 / steps_per_mm);
    if (n < 1.0 || n > 4294967295.0) {  // seed 000 §3.4.6: NUMERATOR is uint32, 1..4,294,967,295
        throw BadInput("machine", "NUMERATOR = clk_hz x 60 / steps_per_mm = " + number_text(n) +
                                      " does not fit uint32 (1..4294967295)");
    }
    return static_cast<std::uint32_t>(n);
}

}  // namespace cnc::host
