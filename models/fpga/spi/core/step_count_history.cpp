#include "fpga/spi/core/step_count_history.hpp"

namespace cnc::fpga {

void StepCountHistory::add_rise(std::int64_t rise_edge, bool forward) {
    // Wraps mod 2^32 like the register; computed unsigned to stay defined.
    m_value = static_cast<std::int32_t>(static_cast<std::uint32_t>(m_value) + (forward ? 1U : 0xFFFF'FFFFU));
    (forward ? m_forward : m_reverse) += 1;
    if (m_size == kKept) {
        m_before_recent = m_recent[m_next].value;
    } else {
        ++m_size;
    }
    m_recent[m_next] = {rise_edge + 1, m_value};
    m_next = (m_next + 1) % kKept;
}

std::int32_t StepCountHistory::value_at_edge(std::int64_t edge) const {
    // Newest first: the register value a load at `edge` sees is the last update at an edge before it.
    for (std::size_t i = 1; i <= m_size; ++i) {
        const Update& u = m_recent[(m_next + kKept - i) % kKept];
        if (u.edge < edge) return u.value;
    }
    return m_before_recent;
}

}  // namespace cnc::fpga
