// Registered outputs of the event-driven FPGA blocks: a block decides a register's next value when its inputs
// change (delta 1 of an edge) and this helper applies it at the exact edge time (delta 0 of that edge), so
// every reader that wakes on a change at edge n sees all of that edge's register updates.
#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <systemc>

#include "common/sc_time.hpp"
#include "common/units.hpp"

namespace cnc::fpga {

class TimedWriter : public sc_core::sc_module {
public:
    explicit TimedWriter(const sc_core::sc_module_name& name);

    // Runs `write` at t_ps (>= now: a write due now runs in the next delta); writes due at the same time run in the
    // order they were scheduled.
    void at(TimePs t_ps, std::function<void()> write);
    [[nodiscard]] std::uint64_t activations() const { return m_activations; }

private:
    void apply_due();
    std::multimap<TimePs, std::function<void()>> m_pending;
    sc_core::sc_event m_wake;
    std::uint64_t m_activations = 0;
};

// Current simulation time in ps (the kernel runs at the default 1 ps resolution).
[[nodiscard]] inline sc_core::sc_time ps(TimePs t) {
    return sc_core::sc_time::from_value(static_cast<sc_dt::uint64>(t));
}

}  // namespace cnc::fpga
