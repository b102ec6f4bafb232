#include "run/job_estimate.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "common/units.hpp"

namespace cnc::sim {

namespace {

// The limit's margins (job_estimate.hpp): twice the estimate, a second per move, ten seconds for the rest.
constexpr double kLimitFactor = 2.0;
constexpr double kLimitPerMoveS = 1.0;
constexpr double kLimitFixedS = 10.0;

double path_speed_mm_per_s(const host::ProgrammedMove& move, const ArchPace& pace) {
    const double feed = move.feed_mm_per_min / kSecondsPerMinute;
    if (move.path.is_arc) return std::min({feed, pace.max_speed_x_mm_per_s, pace.max_speed_y_mm_per_s});
    const geom::Vec2 d = move.path.end - move.path.start;
    const double length = geom::norm(d);
    double speed = feed;
    if (d.x_mm != 0.0) speed = std::min(speed, pace.max_speed_x_mm_per_s * length / std::fabs(d.x_mm));
    if (d.y_mm != 0.0) speed = std::min(speed, pace.max_speed_y_mm_per_s * length / std::fabs(d.y_mm));
    return speed;
}

}  // namespace

EstimateSum::EstimateSum(double waits_s, const ArchPace& pace) : m_pace(pace) {
    // The host waits (dwells, operator pauses, Z moves) take their own time on every architecture.
    m_e.expected_s = pace.startup_s + pace.link_s + waits_s;
}

void EstimateSum::add(const host::ProgrammedMove& move) {
    const double speed = path_speed_mm_per_s(move, m_pace);
    m_e.expected_s += move.path.length_mm() / speed + (m_pace.ramp_s ? m_pace.ramp_s(speed) : 0.0);
    ++m_e.moves;
}

JobEstimate EstimateSum::finish() const {
    JobEstimate e = m_e;
    e.limit_s = kLimitFactor * e.expected_s + kLimitPerMoveS * static_cast<double>(e.moves) + kLimitFixedS;
    return e;
}

JobEstimate estimate_job(const host::Program& program, const ArchPace& pace) {
    EstimateSum sum(program.wait_s_between(0, program.moves.size() + 1), pace);
    for (const host::ProgrammedMove& move : program.moves) sum.add(move);
    return sum.finish();
}

std::string limit_formula(const JobEstimate& estimate) {
    return fmt::format(FMT_STRING("{:.0f} x {:.3f} s + {:.0f} s x {} moves + {:.0f} s"), kLimitFactor,
                       estimate.expected_s, kLimitPerMoveS, estimate.moves, kLimitFixedS);
}

}  // namespace cnc::sim
