#include "fpga/spi/cmd_fifo.hpp"

namespace cnc::fpga {

CmdFifo::CmdFifo(const sc_core::sc_module_name& name, const SpiFpgaConfig& cfg, std::size_t n_axes)
    : sc_module(name), m_clock(clock_grid(cfg)), m_core(cfg.fifo_depth, n_axes) {}

bool CmdFifo::push(std::int64_t edge, std::uint64_t seq, const spi::Command& command) {
    const bool accepted = m_core.push(edge, seq, command);
    if (accepted) m_pushed.notify(sc_core::SC_ZERO_TIME);
    return accepted;
}

FifoStatus CmdFifo::status_at(std::int64_t edge) const {
    const std::uint32_t level = m_core.level_at(edge);
    return {level, level >= m_core.depth(), m_core.drops_before(edge)};
}

void CmdFifo::keep_logs(bool on) {
    m_keep_applied_log = on;
    m_core.keep_push_log(on);
}

bool CmdFifo::readable(std::size_t axis, std::int64_t edge) const {
    return m_core.readable(axis, edge);
}

std::optional<FifoRead> CmdFifo::read(std::size_t axis, std::int64_t edge) {
    const std::optional<FifoRead> r = m_core.read(axis, edge);
    if (r && r->frame_applied) {
        m_last_applied = {edge, m_clock.at(edge), r->seq, r->laser_on};
        if (m_keep_applied_log) m_applied.push_back(m_last_applied);
        m_applied_event.notify(sc_core::SC_ZERO_TIME);
    }
    return r;
}

}  // namespace cnc::fpga
