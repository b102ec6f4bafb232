#include "spi/spi_master.hpp"
#include "common/sc_time.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace cnc::spi {

namespace {
bool bit_of(const std::vector<std::uint8_t>& bytes, std::size_t k) {
    return ((bytes[k / 8] >> (7 - k % 8)) & 1U) != 0;  // MSB first
}
}  // namespace

SpiMaster::SpiMaster(const sc_core::sc_module_name& name, const SpiConfig& cfg)
    : sc_module(name), sclk("sclk"), mosi("mosi"), ss("ss"), miso("miso"), target("target"), m_cfg(cfg) {
    validate(m_cfg);
    // Idle levels before time 0 (no process writes them, so transfer()'s thread stays the only writer).
    sclk.initialize(false);
    mosi.initialize(false);
    ss.initialize(true);
}

void SpiMaster::end_of_elaboration() {
    if (!m_cfg.trace_wires && target.size() == 0)
        throw std::logic_error(std::string(name()) + ": trace_wires = false needs the target port bound");
}

TimePs SpiMaster::pins_quiet_until() const {
    const TimePs now = now_ps();
    if (m_busy) return std::max(now, m_next_pin_change_ps);
    return std::max({now, m_idle_from_ps, m_no_transfer_before_ps});
}

void SpiMaster::wait_until(TimePs t_ps) {
    const TimePs now = now_ps();
    m_next_pin_change_ps = t_ps;
    if (t_ps > now) {
        sc_core::wait(sc_core::sc_time::from_value(static_cast<sc_dt::uint64>(t_ps - now)));
        ++m_activations;
    }
}

void SpiMaster::transfer(const std::vector<std::uint8_t>& out, std::vector<std::uint8_t>& in) {
    if (m_busy) throw std::logic_error(std::string(name()) + ": transfer() called while a transfer runs");
    m_busy = true;
    wait_until(m_idle_from_ps);
    const TimePs t0 = now_ps();
    const std::size_t bits = 8 * out.size();
    const TimePs t_end = t0 + transfer_time_ps(m_cfg, bits);
    std::vector<std::uint8_t> sampled;  // MOSI as the slave samples it, with bit errors on the wire
    if (m_faults) {
        sampled = out;
        if (const std::uint32_t n = m_faults->apply(SpiDirection::Mosi, sampled)) {
            ++m_fault_stats.mosi_frames_hit;
            m_fault_stats.mosi_bits_inverted += n;
            if (!sampled.empty() && sampled[0] != out[0]) ++m_fault_stats.mosi_header_hit;
        }
    }
    const std::vector<std::uint8_t>& on_mosi = m_faults ? sampled : out;
    if (m_cfg.trace_wires) {
        shift_on_wires(on_mosi, in, t0);
        wait_until(t_end);
        ss.write(true);
        mosi.write(false);
    } else {
        target->select(t0);
        wait_until(t_end);
        target->deselect(t_end, on_mosi, in);
    }
    if (m_faults) {
        if (const std::uint32_t n = m_faults->apply(SpiDirection::Miso, in)) {
            ++m_fault_stats.miso_frames_hit;
            m_fault_stats.miso_bits_inverted += n;
        }
    }
    if (m_keep_transfer_log) m_transfers.push_back({t0, t_end, bits});
    ++m_transfer_count;
    m_ss_low_total_ps += t_end - t0;
    m_idle_from_ps = t_end + m_cfg.ss_idle_min_ps;
    m_busy = false;
}

void SpiMaster::shift_on_wires(const std::vector<std::uint8_t>& out, std::vector<std::uint8_t>& in, TimePs t0) {
    const std::size_t bits = 8 * out.size();
    in.assign(out.size(), 0);
    ss.write(false);
    if (bits == 0) return;
    mosi.write(bit_of(out, 0));
    for (std::size_t k = 0; k < bits; ++k) {
        wait_until(t0 + sclk_rise_ps(m_cfg, static_cast<std::int64_t>(k)));
        if (miso.read()) in[k / 8] = static_cast<std::uint8_t>(in[k / 8] | (0x80U >> (k % 8)));
        sclk.write(true);
        wait_until(t0 + sclk_fall_ps(m_cfg, static_cast<std::int64_t>(k)));
        sclk.write(false);
        if (k + 1 < bits) mosi.write(bit_of(out, k + 1));
    }
}

void SpiMaster::add_traces(sc_core::sc_trace_file* tf) const {
    sc_core::sc_trace(tf, sclk, sclk.name());
    sc_core::sc_trace(tf, mosi, mosi.name());
    sc_core::sc_trace(tf, ss, ss.name());
    sc_core::sc_trace(tf, miso, miso.name());
}

}  // namespace cnc::spi
