#include "fpga/core/step_schedule.hpp"

#include <algorithm>
#include <limits>

namespace cnc::fpga {

std::uint32_t abs_steps(std::int32_t steps) {
    const auto bits = static_cast<std::uint32_t>(steps);
    return steps < 0 ? ~bits + 1U : bits;
}

StepPeriods compute_periods(std::uint32_t abs_x, std::uint32_t abs_y, std::uint16_t feed, std::uint32_t num_x,
                            std::uint32_t num_y, const FpgaConfig& cfg) {
    StepPeriods p;
    if (feed == 0) {
        p.x_cycles = p.y_cycles = cfg.feed_zero_period_cycles;
        return p;
    }
    if (abs_x == 0 && abs_y == 0) return p;
    const bool x_dominant = abs_x >= abs_y;
    const std::uint32_t abs_dom = x_dominant ? abs_x : abs_y;
    const std::uint32_t abs_sub = x_dominant ? abs_y : abs_x;
    const std::uint32_t per_step = (x_dominant ? num_x : num_y) / feed;
    std::uint32_t sub = 0;
    if (abs_sub != 0) {
        const std::uint64_t product = std::uint64_t{per_step} * abs_dom;
        constexpr std::uint64_t kMax32 = std::numeric_limits<std::uint32_t>::max();
        p.overflow = product > kMax32;
        if (cfg.period_arithmetic == PeriodArithmetic::Wrap32) {
            sub = static_cast<std::uint32_t>(product) / abs_sub;
        } else {
            sub = static_cast<std::uint32_t>(std::min(product / abs_sub, kMax32));
        }
    }
    p.x_cycles = x_dominant ? per_step : sub;
    p.y_cycles = x_dominant ? sub : per_step;
    return p;
}

AxisPulses::AxisPulses(std::uint32_t steps, std::uint32_t period_cycles, std::uint32_t pulse_high_cycles,
                       std::int64_t exit_edge)
    : m_steps(steps),
      m_period(period_cycles),
      m_high(pulse_high_cycles),
      m_exit(exit_edge),
      m_separate(period_cycles > pulse_high_cycles),
      m_done(steps == 0 || period_cycles == 0) {}

bool AxisPulses::peek(CycleEdge& out) const {
    if (m_done) return false;
    if (m_rising) {
        const std::int64_t j = m_pulse * m_period;
        if (j >= m_exit) return false;  // the exit edge forces STEP low
        out = {j, true};
        return true;
    }
    // cnt == PULSE_HIGH lowers STEP; a short period never gets there and the axis' "rem == 0" branch does.
    const std::int64_t end = m_separate ? m_pulse * m_period + m_high : m_steps * m_period;
    out = {std::min(end, m_exit), false};
    return true;
}

void AxisPulses::pop() {
    if (m_rising) {
        m_rising = false;
        return;
    }
    m_rising = true;
    ++m_pulse;
    if (!m_separate || m_pulse >= m_steps) m_done = true;
}

RampPulses::RampPulses(const RampInputs& in, bool x_dominant, std::uint32_t pulse_high_cycles)
    : m_run(in), m_x_dominant(x_dominant), m_high(pulse_high_cycles) {}

bool RampPulses::next(PinEdge& out) {
    if (m_pending_next == m_pending_size) {
        RampRun::Step step;
        if (!m_run || !m_run->next(step)) return false;
        const bool x = m_x_dominant || step.sub;
        const bool y = !m_x_dominant || step.sub;
        m_pending_size = m_pending_next = 0;
        if (x) m_pending[m_pending_size++] = {step.clock, StepPin::StepX, true};
        if (y) m_pending[m_pending_size++] = {step.clock, StepPin::StepY, true};
        if (x) m_pending[m_pending_size++] = {step.clock + m_high, StepPin::StepX, false};
        if (y) m_pending[m_pending_size++] = {step.clock + m_high, StepPin::StepY, false};
    }
    out = m_pending[m_pending_next++];
    return true;
}

StepSchedule::StepSchedule(const MoveInputs& in, bool dir_x_before, bool dir_y_before, const FpgaConfig& cfg)
    : m_dir_x(dir_level(in.steps_x)),
      m_dir_y(dir_level(in.steps_y)),
      m_run_start(kPeriodsEdge + cfg.dir_settle_cycles) {
    const std::uint32_t abs_x = abs_steps(in.steps_x);
    const std::uint32_t abs_y = abs_steps(in.steps_y);
    m_periods = compute_periods(abs_x, abs_y, in.feed, in.num_x, in.num_y, cfg);
    m_has_run = abs_x != 0 || abs_y != 0;

    m_prologue[m_prologue_size++] = {kBusyRise, StepPin::Busy, true};
    if (m_dir_x != dir_x_before) m_prologue[m_prologue_size++] = {kDirEdge, StepPin::DirX, m_dir_x};
    if (m_dir_y != dir_y_before) m_prologue[m_prologue_size++] = {kDirEdge, StepPin::DirY, m_dir_y};

    if (!m_has_run) return;
    if (cfg.ramp != StepRamp::None) {
        start_ramp(in, abs_x, abs_y, cfg);
        return;
    }
    // RUN exits on the first edge where each axis is on its last cycle or has nothing (left) to do.
    auto last_edge = [](std::uint32_t steps, std::uint32_t period) -> std::int64_t {
        return steps == 0 || period == 0 ? 0 : std::int64_t{steps} * period - 1;
    };
    const std::int64_t exit_edge = std::max(last_edge(abs_x, m_periods.x_cycles), last_edge(abs_y, m_periods.y_cycles));
    m_run_cycles = exit_edge + 1;
    m_x = AxisPulses(abs_x, m_periods.x_cycles, cfg.pulse_high_cycles, exit_edge);
    m_y = AxisPulses(abs_y, m_periods.y_cycles, cfg.pulse_high_cycles, exit_edge);
}

RampInputs ramp_inputs(const MoveInputs& in, const FpgaConfig& cfg) {
    const std::uint32_t abs_x = abs_steps(in.steps_x);
    const std::uint32_t abs_y = abs_steps(in.steps_y);
    const StepPeriods periods = compute_periods(abs_x, abs_y, in.feed, in.num_x, in.num_y, cfg);
    const bool x_dominant = abs_x >= abs_y;
    const std::uint32_t period = x_dominant ? periods.x_cycles : periods.y_cycles;
    return {x_dominant ? abs_x : abs_y,
            x_dominant ? abs_y : abs_x,
            velocity_of_period(period, 2 * std::uint64_t{cfg.pulse_high_cycles}),
            in.ramp_start,
            in.ramp_accel,
            cfg.ramp == StepRamp::SCurve ? in.ramp_jerk : 0};
}

// The ramp runs the move once here for its length (RUN ends with the last step's fall), and once for its edges.
void StepSchedule::start_ramp(const MoveInputs& in, std::uint32_t abs_x, std::uint32_t abs_y, const FpgaConfig& cfg) {
    const bool x_dominant = abs_x >= abs_y;
    const RampInputs ramp = ramp_inputs(in, cfg);
    RampRun run(ramp);
    RampRun::Step step;
    std::int64_t last_rise = 0;
    while (run.next(step)) last_rise = step.clock;
    m_run_cycles = last_rise + cfg.pulse_high_cycles + 1;
    m_ramp.emplace(ramp, x_dominant, cfg.pulse_high_cycles);
}

bool StepSchedule::next(PinEdge& out) {
    if (m_prologue_next < m_prologue_size) {
        out = m_prologue[m_prologue_next++];
        return true;
    }
    if (m_ramp) {
        PinEdge e;
        if (m_ramp->next(e)) {
            out = {m_run_start + e.cycle, e.pin, e.level};
            return true;
        }
        m_ramp.reset();
    }
    CycleEdge ex;
    CycleEdge ey;
    const bool has_x = m_x.peek(ex);
    const bool has_y = m_y.peek(ey);
    if (has_x && (!has_y || ex.cycle <= ey.cycle)) {
        m_x.pop();
        out = {m_run_start + ex.cycle, StepPin::StepX, ex.level};
        return true;
    }
    if (has_y) {
        m_y.pop();
        out = {m_run_start + ey.cycle, StepPin::StepY, ey.level};
        return true;
    }
    if (!m_busy_fall_sent) {
        m_busy_fall_sent = true;
        out = {busy_fall(), StepPin::Busy, false};
        return true;
    }
    return false;
}

TimePs run_duration_ps(const MoveInputs& in, const FpgaConfig& cfg) {
    const StepSchedule schedule(in, false, false, cfg);  // the DIR levels before do not change RUN's length
    return cycles_to_ps(schedule.run_cycles(), cfg.clk_hz);
}

}  // namespace cnc::fpga
