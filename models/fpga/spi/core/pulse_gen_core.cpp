#include "fpga/spi/core/pulse_gen_core.hpp"

#include <algorithm>

namespace cnc::fpga {

PulseGenCore::PulseGenCore(const SpiFpgaConfig& cfg) : m_cfg(cfg) {}

bool PulseGenCore::reads_at(std::int64_t edge) const {
    if (m_cfg.rate_apply == RateApply::Immediately) return true;
    return !m_next_rise || *m_next_rise == edge;
}

bool PulseGenCore::load(std::int64_t edge, const spi::AxisRate& word) {
    m_next_rise.reset();
    m_dir_pending.reset();
    m_period = word.period_cycles;
    if (m_period == 0) return false;
    const std::uint32_t min_period = min_period_cycles(m_cfg);
    const bool stretched = m_period < min_period;
    m_period = std::max(m_period, min_period);

    std::int64_t rise = edge;
    if (word.forward != m_dir) {
        std::int64_t d = edge;
        if (m_last_rise) d = std::max(d, *m_last_rise + m_cfg.dir_hold_cycles);
        m_dir_pending = d;
        rise = std::max(rise, d + m_cfg.dir_setup_cycles);
    } else if (m_last_dir_change) {
        rise = std::max(rise, *m_last_dir_change + m_cfg.dir_setup_cycles);
    }
    if (m_last_rise) {
        const std::int64_t spacing = m_cfg.rate_apply == RateApply::Immediately ? m_period : min_period;
        rise = std::max(rise, *m_last_rise + spacing);
    }
    m_next_rise = rise;
    return stretched;
}

std::optional<GenChange> PulseGenCore::next_change() const {
    std::optional<GenChange> best;
    auto consider = [&best](const std::optional<std::int64_t>& edge, GenPin pin, bool level) {
        if (edge && (!best || *edge < best->edge)) best = GenChange{*edge, pin, level};
    };
    // Considered in tie order: a later candidate wins only when strictly earlier.
    consider(m_fall, GenPin::Step, false);
    consider(m_dir_pending, GenPin::Dir, !m_dir);
    consider(m_next_rise, GenPin::Step, true);
    return best;
}

void PulseGenCore::pop() {
    const auto c = next_change();
    if (!c) return;
    if (c->pin == GenPin::Dir) {
        m_dir = c->level;
        m_last_dir_change = c->edge;
        m_dir_pending.reset();
    } else if (!c->level) {
        m_fall.reset();
    } else {
        m_last_rise = c->edge;
        m_fall = c->edge + m_cfg.pulse_cycles;
        m_next_rise = c->edge + m_period;
    }
}

}  // namespace cnc::fpga
