#include "fpga/spi/core/cmd_fifo_core.hpp"

#include <algorithm>
#include <stdexcept>

namespace cnc::fpga {

CmdFifoCore::CmdFifoCore(std::size_t depth, std::size_t n_axes)
    : m_depth(depth), m_axes(n_axes), m_read_index(n_axes, 0) {}

bool CmdFifoCore::freed_before(const Entry& e, std::int64_t edge) const {
    return std::all_of(e.read_edge.begin(), e.read_edge.end(), [edge](std::int64_t r) { return r >= 0 && r < edge; });
}

void CmdFifoCore::forget(std::int64_t edge) {
    // Every later call has an edge >= `edge`, for which a freed entry no longer counts.
    while (!m_entries.empty() && freed_before(m_entries.front(), edge)) m_entries.pop_front();
}

std::uint32_t CmdFifoCore::level_at(std::int64_t edge) const {
    std::uint32_t level = 0;
    for (const Entry& e : m_entries) {
        if (e.push_edge < edge && !freed_before(e, edge)) ++level;
    }
    return level;
}

bool CmdFifoCore::push(std::int64_t edge, std::uint64_t seq, const spi::Command& command) {
    if (command.axes.size() != m_axes) throw std::logic_error("cmd_fifo: frame with the wrong number of axes");
    forget(edge);
    const std::uint32_t level = level_at(edge);
    const bool full = level >= m_depth;
    if (m_keep_log) m_log.push_back({edge, seq, full, level});
    if (full) {
        ++m_dropped;
        m_drop_edges.push_back(edge);
        return false;
    }
    m_entries.push_back({m_next_index++, seq, edge, command, std::vector<std::int64_t>(m_axes, -1)});
    m_max_level = std::max(m_max_level, level + 1);
    return true;
}

const CmdFifoCore::Entry* CmdFifoCore::next_for(std::size_t axis) const {
    if (m_entries.empty()) return nullptr;
    const std::uint64_t offset = m_read_index.at(axis) - m_entries.front().index;
    return offset < m_entries.size() ? &m_entries[offset] : nullptr;
}

bool CmdFifoCore::readable(std::size_t axis, std::int64_t edge) const {
    const Entry* e = next_for(axis);
    return e != nullptr && e->push_edge < edge;
}

std::optional<FifoRead> CmdFifoCore::read(std::size_t axis, std::int64_t edge) {
    forget(edge);
    if (!readable(axis, edge)) return std::nullopt;
    auto& e = m_entries[m_read_index[axis] - m_entries.front().index];
    e.read_edge[axis] = edge;
    ++m_read_index[axis];
    const bool applied = std::all_of(e.read_edge.begin(), e.read_edge.end(), [](std::int64_t r) { return r >= 0; });
    return FifoRead{e.seq, e.command.axes[axis], applied, e.command.laser_on};
}

std::uint64_t CmdFifoCore::drops_before(std::int64_t edge) const {
    std::uint64_t n = m_dropped;
    for (auto it = m_drop_edges.rbegin(); it != m_drop_edges.rend() && *it >= edge; ++it) --n;
    return n;
}

}  // namespace cnc::fpga
