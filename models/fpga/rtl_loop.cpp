#include "fpga/rtl_loop.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "rtl/plugin_load.hpp"

namespace cnc::fpga {

namespace {

// A batch's length when the inputs are quiet for long: the model reports settled() only at the end of a batch,
// so a design at rest is found within this many edges and the rest are skipped.
constexpr std::uint64_t kMaxBatchCycles = 1U << 20U;
// The farthest the model runs ahead of the simulation time: a promise of "never" (the host is done) still ends in
// a time ClockGrid can count edges to, and a design that never settles (a free-running counter) is not clocked far
// past the end of the run.
constexpr TimePs kMaxAheadPs = kPsPerMs;

}  // namespace

RtlLoop::RtlLoop(const sc_core::sc_module_name& name, const ClockGrid& clock, const rtl::PluginSpec& spec,
                 const rtl::BuiltPlugin& plugin, Wiring wiring, EdgeHandler on_edge)
    : sc_module(name),
      m_clock(clock),
      m_model(rtl::load_model(plugin)),
      m_wiring(std::move(wiring)),
      m_on_edge(std::move(on_edge)),
      m_writer("writer") {
    int next = static_cast<int>(spec.outputs.size());
    for (const bool present : plugin.observed_present) m_observed_index.push_back(present ? next++ : -1);
    m_values.assign(static_cast<std::size_t>(next), 0);
    m_before = m_values;
    m_read = m_values;
    m_quiet_until = [] { return now_ps(); };
    SC_HAS_PROCESS(RtlLoop);
    SC_THREAD(run_thread);
}

std::uint64_t RtlLoop::watched(const std::vector<std::uint64_t>& values, std::size_t net) const {
    const int i = m_observed_index[net];
    return i < 0 ? 0 : values[static_cast<std::size_t>(i)];
}

void RtlLoop::edge(std::int64_t n) {
    for (std::size_t i = 0; i < m_read.size(); ++i) m_read[i] = m_model->value(static_cast<int>(i));
    if (n > 0 && m_read == m_values) return;
    m_before.swap(m_values);
    m_values.swap(m_read);
    const TimePs t = m_clock.at(n);
    for (const Output& out : m_wiring.outputs) {
        const int i = out.port >= 0 ? out.port : m_observed_index[static_cast<std::size_t>(out.net)];
        if (i < 0) continue;
        const bool level = m_values[static_cast<std::size_t>(i)] != 0;
        if (n == 0 || m_values[static_cast<std::size_t>(i)] != m_before[static_cast<std::size_t>(i)]) {
            m_writer.at(t, [pin = out.pin, level] { pin->write(level); });
        }
    }
    m_on_edge(n);
}

void RtlLoop::run_through(TimePs t_ps) {
    const std::int64_t last = m_clock.last_at_or_before(t_ps);
    while (m_next_edge <= last) {
        const auto batch = std::min(static_cast<std::uint64_t>(last - m_next_edge + 1), kMaxBatchCycles);
        m_next_edge += static_cast<std::int64_t>(m_model->run(batch));
        edge(m_next_edge - 1);
        if (m_model->settled()) return;  // every later edge leaves it as it is: the thread skips them
    }
}

bool RtlLoop::input_changed(std::string& which) const {
    for (std::size_t k = 0; k < m_wiring.inputs.size(); ++k) {
        if (m_wiring.inputs[k].pin->read() != m_levels[k]) {
            which = m_wiring.inputs[k].pin->name();
            return true;
        }
    }
    return false;
}

void RtlLoop::run_thread() {
    // Edge 0 is the reset state (the tops' rst_n is synchronous), with the inputs at their initial levels.
    sc_core::sc_event_or_list input_events;
    for (const Input& in : m_wiring.inputs) {
        m_levels.push_back(in.pin->read());
        m_model->set_input(in.input, m_levels.back() ? 1 : 0);
        input_events |= in.pin->value_changed_event();
    }
    m_model->set_input(m_wiring.reset_n, 0);
    m_model->run(1);
    m_next_edge = 1;
    edge(0);
    m_model->set_input(m_wiring.reset_n, 1);
    for (;;) {
        const TimePs now = now_ps();
        std::string which;
        if (input_changed(which)) {
            if (now < m_promised_ps) {
                throw std::logic_error(std::string(name()) + ": " + which + " changed at " + std::to_string(now) +
                                       " ps, before the " + std::to_string(m_promised_ps) + " ps promised");
            }
            run_through(now);  // an edge at the change's instant samples the level before it
            for (std::size_t k = 0; k < m_wiring.inputs.size(); ++k) {
                const bool level = m_wiring.inputs[k].pin->read();
                if (level == m_levels[k]) continue;
                m_levels[k] = level;
                m_model->set_input(m_wiring.inputs[k].input, level ? 1 : 0);
            }
        }
        m_promised_ps = std::max(now, std::min(m_quiet_until(), now + kMaxAheadPs));
        run_through(m_promised_ps);
        if (!m_model->settled()) {
            if (!m_at_rest || !m_at_rest() || sc_core::sc_pending_activity()) {
                wait(ps(m_clock.at(m_next_edge) - now), input_events);
                continue;
            }
            // At rest with nothing left to drive an input: the run ends here. An input changing after all would
            // find the edges not run.
            wait(input_events);
            throw std::logic_error(std::string(name()) + ": an input changed at " + std::to_string(now_ps()) +
                                   " ps after the design was left at rest with nothing pending");
        }
        // Nothing changes until an input does (an idle design): the edges until then are skipped, and a run whose
        // other models have finished ends here.
        wait(input_events);
        m_next_edge = std::max(m_next_edge, m_clock.first_after(now_ps()));
    }
}

}  // namespace cnc::fpga
