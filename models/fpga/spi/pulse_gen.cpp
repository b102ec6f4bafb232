#include "fpga/spi/pulse_gen.hpp"

#include <algorithm>

#include "fpga/timed_writer.hpp"

namespace cnc::fpga {

PulseGen::PulseGen(const sc_core::sc_module_name& name, const SpiFpgaConfig& cfg, std::size_t axis)
    : sc_module(name), step("step"), dir("dir"), fifo("fifo"), m_axis(axis), m_clock(clock_grid(cfg)), m_core(cfg) {
    SC_HAS_PROCESS(PulseGen);
    step.initialize(false);  // reset levels
    dir.initialize(false);
    SC_METHOD(on_push);
    sensitive << fifo;  // CmdFifo's default event: a frame was written at the current edge
    dont_initialize();
    SC_METHOD(on_wake);
    sensitive << m_wake;
    dont_initialize();
}

void PulseGen::on_push() {
    ++m_activations;
    // Written at this edge, readable from the next one.
    const std::int64_t readable_edge = m_clock.last_at_or_before(now_ps()) + 1;
    m_read_due = m_read_due ? std::min(*m_read_due, readable_edge) : readable_edge;
    schedule();
}

std::vector<AppliedRate> PulseGen::take_applied() {
    std::vector<AppliedRate> out;
    out.swap(m_applied);
    return out;
}

void PulseGen::on_wake() {
    ++m_activations;
    const std::int64_t edge = m_clock.last_at_or_before(now_ps());
    if (m_read_due && *m_read_due <= edge) m_read_due.reset();
    if (m_core.reads_at(edge)) {
        if (const auto entry = fifo->read(m_axis, edge)) {
            const bool stretched = m_core.load(edge, entry->rate);
            m_stretched += stretched ? 1 : 0;
            m_applied.push_back({edge, m_clock.at(edge), entry->seq, entry->rate, stretched});
            ++m_applied_count;
            // One read per edge: a further entry is considered from the next edge.
            if (fifo->readable(m_axis, edge + 1)) m_read_due = edge + 1;
        }
    }
    for (auto c = m_core.next_change(); c && c->edge == edge; c = m_core.next_change()) {
        (c->pin == GenPin::Dir ? dir : step).write(c->level);
        m_core.pop();
    }
    schedule();
}

void PulseGen::schedule() {
    std::optional<std::int64_t> next = m_read_due;
    if (const auto c = m_core.next_change()) next = next ? std::min(*next, c->edge) : c->edge;
    if (!next) return;
    // An earlier pending notification wins; on_wake reschedules after it.
    m_wake.notify(ps(m_clock.at(*next) - now_ps()));
}

}  // namespace cnc::fpga
