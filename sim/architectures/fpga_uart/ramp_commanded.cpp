#include "architectures/fpga_uart/ramp_commanded.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "fpga/core/step_ramp.hpp"
#include "fpga/core/step_schedule.hpp"

namespace cnc::sim::fpga_uart {

namespace {

constexpr double kSecondsPerMinute = 60.0;
// Below every step's spacing at the start speed, so that no axis turns twice between two scan points.
constexpr TimePs kScanStepPs = 100 * kPsPerUs;

// The S-curve step_gen plans for the move, on the FPGA's clock of `hz`.
RampProfile scurve_profile(const fpga::RampInputs& ramp, double hz) {
    const std::uint64_t start = fpga::ramp_start_velocity(ramp);
    const fpga::ScurvePlan plan = fpga::plan_scurve(start, ramp.cruise, ramp.accel_reg, ramp.jerk_reg, ramp.abs_dom);
    const double one = static_cast<double>(fpga::kPhaseOne);
    RampProfile::SCurve climb;
    climb.jerk_steps_per_s3 = std::ldexp(static_cast<double>(ramp.jerk_reg), -fpga::kJerkShift) / one * hz * hz * hz;
    climb.jerk_s = static_cast<double>(plan.jerk_clocks) / hz;
    climb.top_s = static_cast<double>(plan.top_clocks) / hz;
    return {static_cast<double>(ramp.abs_dom), static_cast<double>(start) / one * hz, climb};
}

}  // namespace

RampProfile::RampProfile(double steps, double start_steps_per_s, double accel_steps_per_s2, double cruise_steps_per_s)
    : m_steps(steps), m_start(std::min(start_steps_per_s, cruise_steps_per_s)), m_accel(accel_steps_per_s2) {
    // Between the first step (at 1/2) and the last (at N - 1/2) the two ramps and the cruise cover N - 1 steps.
    const double between = std::max(steps - 1.0, 0.0);
    const double full_ramp =
        m_accel > 0.0 ? (cruise_steps_per_s * cruise_steps_per_s - m_start * m_start) / (2 * m_accel) : 0.0;
    if (m_accel <= 0.0) {
        m_peak = m_start;
        m_ramp_steps = 0.0;
    } else if (2 * full_ramp <= between) {
        m_peak = std::max(cruise_steps_per_s, m_start);
        m_ramp_steps = full_ramp;
    } else {
        m_peak = std::sqrt(m_start * m_start + m_accel * between);
        m_ramp_steps = between / 2;
    }
    m_ramp_s = m_accel > 0.0 ? (m_peak - m_start) / m_accel : 0.0;
    m_cruise_s = (between - 2 * m_ramp_steps) / m_peak;
}

RampProfile::RampProfile(double steps, double start_steps_per_s, const SCurve& climb)
    : m_steps(steps),
      m_start(start_steps_per_s),
      m_accel(climb.jerk_steps_per_s3 * climb.jerk_s),
      m_jerk_s(climb.jerk_s) {
    m_ramp_s = 2 * climb.jerk_s + climb.top_s;
    m_peak = m_start + m_accel * (climb.jerk_s + climb.top_s);
    // The climb's mean speed is halfway (its acceleration reads the same from either end).
    m_ramp_steps = (m_start + m_peak) / 2 * m_ramp_s;
    m_cruise_s = std::max(std::max(steps - 1.0, 0.0) - 2 * m_ramp_steps, 0.0) / m_peak;
}

// The descent mirrors the climb in time, and the climb's acceleration is symmetric, so the speed the descent has
// lost s seconds in is what the climb had gained: both use gained() from their own start.
double RampProfile::gained(double tau_s) const {
    if (tau_s < m_jerk_s) return m_accel / m_jerk_s * tau_s * tau_s / 2;
    const double top_end_s = m_ramp_s - m_jerk_s;
    if (tau_s <= top_end_s) return m_accel * m_jerk_s / 2 + m_accel * (tau_s - m_jerk_s);
    const double left_s = m_ramp_s - tau_s;
    return m_peak - m_start - m_accel / m_jerk_s * left_s * left_s / 2;
}

double RampProfile::gained_distance(double tau_s) const {
    if (tau_s < m_jerk_s) return m_accel / m_jerk_s * tau_s * tau_s * tau_s / 6;
    const double top_end_s = m_ramp_s - m_jerk_s;
    const double jerk_steps = m_accel * m_jerk_s * m_jerk_s / 6;
    if (tau_s <= top_end_s) {
        const double top = tau_s - m_jerk_s;
        return jerk_steps + m_accel * m_jerk_s / 2 * top + m_accel * top * top / 2;
    }
    const double left_s = m_ramp_s - tau_s;
    return (m_peak - m_start) * (m_ramp_s / 2 - left_s) + m_accel / m_jerk_s * left_s * left_s * left_s / 6;
}

double RampProfile::position(double tau_s) const {
    if (tau_s < 0.0) return 0.0;
    double p = 0.5;
    const double up = std::min(tau_s, m_ramp_s);
    p += m_start * up + gained_distance(up);
    if (tau_s <= m_ramp_s) return p;
    const double cruise = std::min(tau_s - m_ramp_s, m_cruise_s);
    p += m_peak * cruise;
    if (tau_s <= m_ramp_s + m_cruise_s) return p;
    const double down = std::min(tau_s - m_ramp_s - m_cruise_s, m_ramp_s);
    p += m_peak * down - gained_distance(down);
    if (tau_s <= 2 * m_ramp_s + m_cruise_s) return p;
    return std::min(p + m_start * (tau_s - 2 * m_ramp_s - m_cruise_s), m_steps);
}

double RampProfile::velocity(double tau_s) const {
    if (tau_s < 0.0 || tau_s >= duration_s()) return 0.0;
    if (tau_s <= m_ramp_s) return m_start + gained(tau_s);
    if (tau_s <= m_ramp_s + m_cruise_s) return m_peak;
    if (tau_s <= 2 * m_ramp_s + m_cruise_s) return m_peak - gained(tau_s - m_ramp_s - m_cruise_s);
    return m_start;
}

RampCommanded::RampCommanded(const fpga::FpgaConfig& cfg, const InitRegisters& registers, geom::Vec2 origin_mm,
                             std::array<double, 2> steps_per_mm)
    : m_cfg(cfg),
      m_registers(registers),
      m_steps_per_mm(steps_per_mm),
      m_moves(std::make_shared<Moves>()),
      m_at_mm(origin_mm),
      m_segments(2) {
    m_moves->origin_mm = origin_mm;
}

void RampCommanded::read(const fpga::Board& fpga, TimePs now_ps) {
    for (; m_next_record < fpga.packet_count(); ++m_next_record) {
        const fpga::PacketRecord r = fpga.packet(m_next_record);
        if (!r.accepted) continue;
        if (r.t_run_start_ps < 0) {
            if (r.t_busy_fall_ps < 0) return;  // not begun yet
            continue;                          // a move of no steps
        }
        if (r.t_run_start_ps > now_ps) return;
        add(r, fpga.clock());
    }
}

// The move as step_gen runs it: its steps on the clocks of fpga/core/step_ramp.hpp, and its trapezoid at the
// registers' start speed and acceleration on the FPGA's clock, up to the packet's feed on the dominant axis.
void RampCommanded::add(const fpga::PacketRecord& r, const ClockGrid& clock) {
    const fpga::MoveInputs in = move_inputs(r.steps_x, r.steps_y, r.feed, m_registers);
    const fpga::RampInputs ramp = fpga::ramp_inputs(in, m_cfg);
    const bool x_dominant = std::llabs(r.steps_x) >= std::llabs(r.steps_y);
    const std::size_t dom = x_dominant ? 0 : 1;
    const auto hz = static_cast<double>(clock.hz());
    const double one = static_cast<double>(fpga::kPhaseOne);
    const double start = static_cast<double>(std::uint64_t{ramp.start_reg} << fpga::kStartShift) / one * hz;
    const RampProfile profile =
        m_cfg.ramp == fpga::StepRamp::SCurve
            ? scurve_profile(ramp, hz)
            : RampProfile(ramp.abs_dom, start, static_cast<double>(ramp.accel_reg) / one * hz * hz,
                          r.feed / kSecondsPerMinute * m_steps_per_mm[dom]);

    const std::int64_t run_start = clock.last_at_or_before(r.t_run_start_ps);
    const TimePs t0_ps = clock.at(run_start);
    const geom::Vec2 travel{static_cast<double>(r.steps_x) / m_steps_per_mm[0],
                            static_cast<double>(r.steps_y) / m_steps_per_mm[1]};
    Move m{t0_ps, t0_ps + s_to_ps(profile.duration_s()), 0, m_at_mm, travel, profile};
    m.latest_end_ps = m_moves->moves.empty() ? m.t_end_ps : std::max(m.t_end_ps, m_moves->moves.back().latest_end_ps);
    m_at_mm = m_at_mm + travel;

    // A ramp's step is a run of its own at the trapezoid's rate at its instant; the cruise one run from its first
    // step (the other axis at its share of the dominant rate).
    const double share = ramp.abs_dom > 0 ? static_cast<double>(ramp.abs_sub) / ramp.abs_dom : 0.0;
    std::array<bool, 2> in_cruise{false, false};
    fpga::RampRun run(ramp);
    fpga::RampRun::Step step;
    while (run.next(step)) {
        const TimePs t_ps = clock.at(run_start + step.clock);
        const double rate = step.cruising ? profile.peak_steps_per_s() : profile.velocity(ps_to_s(t_ps - t0_ps));
        for (std::size_t axis : {dom, 1 - dom}) {
            const bool sub = axis != dom;
            if (sub && !step.sub) continue;
            if (step.cruising && in_cruise[axis]) continue;
            in_cruise[axis] = step.cruising;
            m_segments[axis].push_back({t_ps, sub ? rate * share : rate});
        }
    }
    m_moves->moves.push_back(std::move(m));
}

metrics::CommandedState RampCommanded::Moves::at(TimePs t_ps) const {
    const auto after =
        std::upper_bound(moves.begin(), moves.end(), t_ps, [](TimePs t, const Move& m) { return t < m.t0_ps; });
    if (after == moves.begin()) return {origin_mm, {}};
    // The last move begun by t_ps ends where its travel takes it; each begun move still under way by then (they
    // overlap only in their last half step) has the rest of its travel still to go.
    const Move& last = *std::prev(after);
    metrics::CommandedState s{last.from_mm + last.travel_mm, {}};
    for (auto m = std::prev(after);; --m) {
        const double tau_s = ps_to_s(t_ps - m->t0_ps);
        const double steps = m->profile.steps();
        s.pos_mm = s.pos_mm - m->travel_mm * ((steps - m->profile.position(tau_s)) / steps);
        s.vel_mm_per_s = s.vel_mm_per_s + m->travel_mm * (m->profile.velocity(tau_s) / steps);
        if (m == moves.begin() || std::prev(m)->latest_end_ps <= t_ps) break;
    }
    return s;
}

metrics::CommandedTrajectory RampCommanded::trajectory(TimePs t_end_ps) const {
    metrics::CommandedTrajectory c;
    c.origin_mm = m_moves->origin_mm;
    c.t_begin_ps = 0;
    c.t_end_ps = t_end_ps;
    c.scan_step_ps = kScanStepPs;
    c.state_at = [moves = m_moves](TimePs t) { return moves->at(t); };
    return c;
}

std::vector<std::vector<metrics::RateSegment>> RampCommanded::take_segments() {
    std::vector<std::vector<metrics::RateSegment>> out(2);
    std::swap(out, m_segments);
    return out;
}

}  // namespace cnc::sim::fpga_uart
