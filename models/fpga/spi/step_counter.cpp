#include "fpga/spi/step_counter.hpp"

#include <stdexcept>
#include <string>

#include "fpga/timed_writer.hpp"

namespace cnc::fpga {

StepCounter::StepCounter(const sc_core::sc_module_name& name, const SpiFpgaConfig& cfg)
    : sc_module(name), step("step"), dir("dir"), m_clock(clock_grid(cfg)) {
    SC_HAS_PROCESS(StepCounter);
    SC_METHOD(on_step_rise);
    sensitive << step.pos();
    dont_initialize();
}

void StepCounter::on_step_rise() {
    ++m_activations;
    const TimePs now = now_ps();
    const std::int64_t edge = m_clock.last_at_or_before(now);
    // STEP is a register of this clock domain: it only changes on clock edges.
    if (m_clock.at(edge) != now) throw std::logic_error(std::string(name()) + ": STEP rose between clock edges");
    // DIR as registered at that edge (setup >= 1 keeps it from changing at the same edge).
    m_history.add_rise(edge, dir.read());
}

}  // namespace cnc::fpga
