#include "fpga/core/step_ramp.hpp"

#include <algorithm>
#include <limits>

namespace cnc::fpga {

namespace {

constexpr std::int64_t kUnbounded = std::numeric_limits<std::int64_t>::max();

// The phase accumulator after clocks 0..n of a stretch entered with `phase` and velocity v, before its wrap.
RampWide accumulated(std::uint64_t phase, std::uint64_t v, const RampGain& gain, std::int64_t n) {
    return RampWide{phase} + (RampWide{n} + 1) * RampWide{v} + gain.phase;
}

RampWide accumulated(std::uint64_t phase, std::uint64_t v, const RampStretch& s, std::int64_t n) {
    return accumulated(phase, v, stretch_gain(s, n), n);
}

// The clock by which a velocity of at least v carries.
std::int64_t carry_bound(std::uint64_t phase, std::uint64_t v) {
    const std::uint64_t left = kPhaseOne - phase;
    return static_cast<std::int64_t>((left + v - 1) / v) - 1;
}

// The first clock n in 0..last whose accumulation carries, or -1. The velocity stays above 0, so the accumulation
// grows with n; and it moves one way over a stretch, so the carry comes no sooner than the faster of its values at
// clocks 0 and `last` would bring it, and no later than the slower.
std::int64_t first_carry(std::uint64_t phase, std::uint64_t v, const RampStretch& s, std::int64_t last) {
    const auto v_last = static_cast<std::uint64_t>(RampWide{v} + stretch_gain(s, last).velocity);
    std::int64_t hi = std::min(last, carry_bound(phase, std::min(v, v_last)));
    if (accumulated(phase, v, s, hi) < RampWide{kPhaseOne}) return -1;
    std::int64_t lo = std::min(hi, carry_bound(phase, std::max(v, v_last)));
    while (lo < hi) {
        const std::int64_t mid = lo + (hi - lo) / 2;
        if (accumulated(phase, v, s, mid) >= RampWide{kPhaseOne}) {
            hi = mid;
        } else {
            lo = mid + 1;
        }
    }
    return lo;
}

}  // namespace

std::uint64_t ramp_start_velocity(const RampInputs& in) {
    return std::max<std::uint64_t>(std::min(std::uint64_t{in.start_reg} << kStartShift, in.cruise), 1);
}

std::uint64_t velocity_of_period(std::uint64_t period_cycles, std::uint64_t min_period_cycles) {
    return kPhaseOne / std::max({period_cycles, min_period_cycles, std::uint64_t{1}});
}

RampRun::RampRun(const RampInputs& in)
    : m_in(in),
      m_start(ramp_start_velocity(in)),
      m_phase(kPhaseOne - m_start),
      m_velocity(m_start),
      m_error(in.abs_dom / 2),
      m_plan(in.jerk_reg == 0 ? ScurvePlan{} : plan_scurve(m_start, in.cruise, in.accel_reg, in.jerk_reg, in.abs_dom)) {
}

std::uint64_t RampRun::decelerated(std::uint64_t v) const {
    return v >= m_start + m_in.accel_reg ? v - m_in.accel_reg : m_start;
}

void RampRun::update_after_step(std::uint64_t v, bool clamp_clock) {
    switch (m_state) {
        case Phase::Accel:
            if (2 * std::uint64_t{m_done} > m_in.abs_dom) {
                m_state = Phase::Decel;
                m_velocity = decelerated(v);
            } else if (clamp_clock) {
                m_state = Phase::Cruise;
                m_ramp_steps = m_done;
                m_velocity = m_in.cruise;
            } else {
                m_velocity = v + m_in.accel_reg;
            }
            return;
        case Phase::Cruise:
            if (m_in.abs_dom - m_done < m_ramp_steps) {
                m_state = Phase::Decel;
                m_velocity = decelerated(v);
            }
            return;
        case Phase::Decel:
            m_velocity = decelerated(v);
            return;
    }
}

RampStretch RampRun::trapezoid_stretch() const {
    const std::uint64_t accel = std::uint64_t{m_in.accel_reg} << kJerkShift;
    if (m_state == Phase::Accel && (accel > 0 || m_velocity == m_in.cruise)) {
        const std::uint64_t need = m_in.cruise - m_velocity;
        return {accel, 0, false,
                need == 0 ? 1 : static_cast<std::int64_t>((need + m_in.accel_reg - 1) / m_in.accel_reg)};
    }
    if (m_state == Phase::Decel && accel > 0 && m_velocity > m_start) {
        return {accel, 0, true,
                static_cast<std::int64_t>((m_velocity - m_start + m_in.accel_reg - 1) / m_in.accel_reg)};
    }
    return {0, 0, false, kUnbounded};
}

// Each phase of the S-curve's acceleration (and of its mirror) is one stretch; the cruise holds.
RampStretch RampRun::scurve_stretch() {
    const std::int64_t t = m_plan.clocks();
    if (m_state == Phase::Accel && m_ramp_clock >= t) {
        m_state = Phase::Cruise;
        m_ramp_steps = m_done;
    }
    if (m_state == Phase::Cruise || m_ramp_clock >= t) return {0, 0, false, kUnbounded};
    return m_plan.stretch_at(m_ramp_clock, m_state == Phase::Decel);
}

void RampRun::end_stretch(const RampStretch& s) {
    if (m_in.jerk_reg != 0) {
        m_velocity = static_cast<std::uint64_t>(static_cast<RampWide>(m_velocity) + stretch_gain(s, s.length).velocity);
        m_ramp_clock += s.length;
    } else if (m_state == Phase::Accel) {
        m_state = Phase::Cruise;
        m_ramp_steps = m_done;
        m_velocity = m_in.cruise;
    } else {
        m_velocity = m_start;
    }
}

void RampRun::scurve_after_step(std::uint64_t v, const RampStretch& s, std::int64_t n) {
    if (m_state == Phase::Cruise) {
        if (m_in.abs_dom - m_done < m_ramp_steps) {
            m_state = Phase::Decel;
            m_ramp_clock = 0;
        }
        return;
    }
    m_velocity = static_cast<std::uint64_t>(static_cast<std::int64_t>(v) + stretch_increment(s, n));
    if (s.length != kUnbounded) m_ramp_clock += n + 1;
}

bool RampRun::next(Step& out) {
    if (m_done >= m_in.abs_dom) return false;
    const bool scurve = m_in.jerk_reg != 0;
    for (;;) {
        const RampStretch s = scurve ? scurve_stretch() : trapezoid_stretch();
        // The velocity never falls below the start's, and falls only in a slowing stretch.
        const std::int64_t last = std::min(s.length - 1, carry_bound(m_phase, s.slowing ? m_start : m_velocity));
        const std::int64_t n = first_carry(m_phase, m_velocity, s, last);
        if (n < 0) {  // the stretch ends without a step
            m_phase = static_cast<std::uint64_t>(accumulated(m_phase, m_velocity, s, s.length - 1));
            m_clock += s.length;
            end_stretch(s);
            continue;
        }
        const RampGain gain = stretch_gain(s, n);
        const auto v = static_cast<std::uint64_t>(static_cast<RampWide>(m_velocity) + gain.velocity);
        m_phase = static_cast<std::uint64_t>(accumulated(m_phase, m_velocity, gain, n) - RampWide{kPhaseOne});
        out.clock = m_clock + n;
        ++m_done;
        m_error += m_in.abs_sub;
        out.sub = m_error >= m_in.abs_dom;
        if (out.sub) m_error -= m_in.abs_dom;
        out.cruising = m_state == Phase::Cruise;
        if (scurve) {
            scurve_after_step(v, s, n);
        } else {
            update_after_step(v, m_state == Phase::Accel && n == s.length - 1);
        }
        m_clock = out.clock + 1;
        return true;
    }
}

}  // namespace cnc::fpga
