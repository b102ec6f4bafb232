#include "fpga/spi/core/observed_spi_records.hpp"

#include <algorithm>
#include <stdexcept>

namespace cnc::fpga {

namespace {

bool same(const SpiFpgaStats& a, const SpiFpgaStats& b) {
    return a.frames == b.frames && a.frames_accepted == b.frames_accepted && a.fifo_drops == b.fifo_drops &&
           a.fifo_max_level == b.fifo_max_level && a.stretched_words == b.stretched_words &&
           a.words_applied == b.words_applied && a.counts == b.counts;
}

}  // namespace

void ObservedSpiRecords::edge(std::int64_t n, const SpiNets& before, const SpiNets& now, TimePs sim_now_ps) {
    const TimePs t = m_clock.at(n);
    // Edge n acts on the state after edge n - 1, which `before` holds: FrameStart, FrameEnd and the FIFO reads.
    if (before.ss_fell) ++m_stats.frames;
    for (std::size_t a = 0; a < m_applied.size(); ++a) {
        if (!before.rd[a]) continue;
        if (m_read_ahead[a] >= m_fifo_seq.size()) throw std::logic_error("rtl spi records: a read of an empty FIFO");
        const spi::AxisRate rate = before.read_port[a];
        const bool stretched = rate.period_cycles != 0 && now.period_cycles[a] != rate.period_cycles;
        m_applied[a].push_back({n, t, m_fifo_seq[m_read_ahead[a]], rate, stretched});
        ++m_read_ahead[a];
        ++m_stats.words_applied[a];
        m_stats.stretched_words += stretched ? 1 : 0;
    }
    // A frame every axis has read leaves the FIFO.
    while (!m_fifo_seq.empty() && std::min(m_read_ahead[0], m_read_ahead[1]) > 0) {
        m_fifo_seq.pop_front();
        --m_read_ahead[0];
        --m_read_ahead[1];
    }
    if (before.ss_rose && before.accepted) {
        ++m_stats.frames_accepted;
        if (before.fifo_full) {
            ++m_stats.fifo_drops;
        } else {
            m_fifo_seq.push_back(m_stats.frames - 1);  // the frame started last
            m_stats.fifo_max_level = std::max(m_stats.fifo_max_level, before.fifo_level + 1);
        }
    }
    m_stats.counts = now.counts;

    if (!same(m_stats, m_snapshots.back().second)) m_snapshots.emplace_back(t, m_stats);
    // The counts before the simulation time no reader asks for any more.
    while (m_snapshots.size() > 1 && m_snapshots[1].first <= sim_now_ps) m_snapshots.pop_front();
}

std::vector<AppliedRate> ObservedSpiRecords::take_applied(std::size_t axis, TimePs t_ps) {
    std::vector<AppliedRate> out;
    std::deque<AppliedRate>& applied = m_applied.at(axis);
    while (!applied.empty() && applied.front().t_ps <= t_ps) {
        out.push_back(applied.front());
        applied.pop_front();
    }
    return out;
}

SpiFpgaStats ObservedSpiRecords::stats(TimePs t_ps) const {
    for (auto it = m_snapshots.rbegin(); it != m_snapshots.rend(); ++it) {
        if (it->first <= t_ps) return it->second;
    }
    return m_snapshots.front().second;
}

}  // namespace cnc::fpga
