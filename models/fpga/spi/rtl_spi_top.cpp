#include "fpga/spi/rtl_spi_top.hpp"

#include <vector>

#include "common/sc_time.hpp"
#include "fpga/spi/core/spi_rtl_design.hpp"

namespace cnc::fpga {

RtlSpiTop::RtlSpiTop(const sc_core::sc_module_name& name, const SpiFpgaConfig& cfg, const rtl::Design& design)
    : SpiBoard(name),
      m_cfg((validate(cfg), cfg)),
      m_clock(clock_grid(cfg)),
      m_spec(spi_rtl_plugin_spec(cfg, design)),
      m_plugin(rtl::build_plugin(m_spec)),
      m_records(m_clock),
      m_loop("rtl", m_clock, m_spec, m_plugin,
             {kSpiRtlInResetN,
              {{&sclk, kSpiRtlInSclk}, {&mosi, kSpiRtlInMosi}, {&ss, kSpiRtlInSs}},
              {{&miso, kSpiRtlOutMiso},
               {&step_x, kSpiRtlOutStepX},
               {&dir_x, kSpiRtlOutDirX},
               {&step_y, kSpiRtlOutStepY},
               {&dir_y, kSpiRtlOutDirY},
               {&laser, kSpiRtlOutLaser}}},
             [this](std::int64_t n) { on_edge(n); }) {
    const std::vector<SpiRtlNet> rest_nets = {kSpiNetAvailX,   kSpiNetAvailY,   kSpiNetRunningX,
                                              kSpiNetRunningY, kSpiNetDirPendX, kSpiNetDirPendY};
    // A user's design without these nets is clocked to the end of the run.
    for (const SpiRtlNet n : rest_nets) {
        if (!m_loop.has_net(n)) return;
    }
    m_loop.at_rest_when([this, rest_nets] {
        for (const SpiRtlNet n : rest_nets) {
            if (m_loop.observed(n) != 0) return false;
        }
        return m_loop.port(kSpiRtlOutStepX) == 0 && m_loop.port(kSpiRtlOutStepY) == 0;
    });
}

SpiNets RtlSpiTop::nets(bool before) const {
    const auto net = [&](SpiRtlNet i) { return before ? m_loop.observed_before(i) : m_loop.observed(i); };
    SpiNets v;
    v.ss_fell = net(kSpiNetSsFell) != 0;
    v.ss_rose = net(kSpiNetSsRose) != 0;
    v.accepted = net(kSpiNetAccepted) != 0;
    v.fifo_full = net(kSpiNetFifoFull) != 0;
    v.fifo_level = static_cast<std::uint32_t>(net(kSpiNetFifoLevel));
    v.rd = {net(kSpiNetRdX) != 0, net(kSpiNetRdY) != 0};
    v.read_port[0] = {static_cast<std::uint32_t>(net(kSpiNetWordPeriodX)), net(kSpiNetWordDirX) != 0};
    v.read_port[1] = {static_cast<std::uint32_t>(net(kSpiNetWordPeriodY)), net(kSpiNetWordDirY) != 0};
    v.period_cycles = {static_cast<std::uint32_t>(net(kSpiNetPeriodX)),
                       static_cast<std::uint32_t>(net(kSpiNetPeriodY))};
    v.counts = {static_cast<std::int32_t>(static_cast<std::uint32_t>(net(kSpiNetCountX))),
                static_cast<std::int32_t>(static_cast<std::uint32_t>(net(kSpiNetCountY)))};
    return v;
}

void RtlSpiTop::on_edge(std::int64_t n) {
    if (n == 0) return;  // the reset state: nothing has happened yet
    m_records.edge(n, nets(true), nets(false), now_ps());
}

std::vector<AppliedRate> RtlSpiTop::take_applied(std::size_t axis) {
    return m_records.take_applied(axis, now_ps());
}

SpiFpgaStats RtlSpiTop::stats() const {
    return m_records.stats(now_ps());
}

}  // namespace cnc::fpga
