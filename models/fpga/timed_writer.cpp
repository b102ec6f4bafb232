#include "fpga/timed_writer.hpp"

#include <stdexcept>

namespace cnc::fpga {

TimedWriter::TimedWriter(const sc_core::sc_module_name& name) : sc_module(name) {
    SC_HAS_PROCESS(TimedWriter);
    SC_METHOD(apply_due);
    sensitive << m_wake;
    dont_initialize();
}

void TimedWriter::at(TimePs t_ps, std::function<void()> write) {
    const TimePs now = now_ps();
    if (t_ps < now) throw std::logic_error(std::string(name()) + ": register write in the past");
    m_pending.emplace(t_ps, std::move(write));
    m_wake.notify(ps(m_pending.begin()->first - now));  // an earlier pending notification is kept
}

void TimedWriter::apply_due() {
    ++m_activations;
    const TimePs now = now_ps();
    while (!m_pending.empty() && m_pending.begin()->first <= now) {
        m_pending.begin()->second();
        m_pending.erase(m_pending.begin());
    }
    if (!m_pending.empty()) m_wake.notify(ps(m_pending.begin()->first - now));
}

}  // namespace cnc::fpga
