// Seed 004's FPGA as Verilog (ours: rtl/spi_fpga_top.v, or the user's) verilated and clocked in the loop
// (fpga/rtl_loop.hpp): its batches run up to the time before which SS, SCLK and MOSI cannot change (what the SPI
// master promises: inputs_quiet_until). It has no transaction path: the master must drive the wires. The records
// come from the design's own nets (ObservedSpiRecords); a design without them keeps its pins and empty records.
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <systemc>
#include <utility>
#include <vector>

#include "fpga/rtl_loop.hpp"
#include "fpga/spi/core/observed_spi_records.hpp"
#include "fpga/spi/core/spi_fpga_config.hpp"
#include "fpga/spi/spi_board.hpp"
#include "rtl/plugin_build.hpp"

namespace cnc::fpga {

class RtlSpiTop final : public SpiBoard {
public:
    // Builds the plug-in (or takes it from the cache): BadInput from rtl::build_plugin.
    RtlSpiTop(const sc_core::sc_module_name& name, const SpiFpgaConfig& cfg, const rtl::Design& design);

    // The earliest time SS, SCLK or MOSI may change, asked at the current time (>= now). Until given: now.
    void inputs_quiet_until(std::function<TimePs()> quiet_until_ps) {
        m_loop.inputs_quiet_until(std::move(quiet_until_ps));
    }

    [[nodiscard]] const SpiFpgaConfig& config() const override { return m_cfg; }
    [[nodiscard]] std::vector<AppliedRate> take_applied(std::size_t axis) override;
    [[nodiscard]] SpiFpgaStats stats() const override;
    // Clock edges the model has run, and how the plug-in was obtained.
    [[nodiscard]] std::int64_t cycles() const { return m_loop.cycles(); }
    [[nodiscard]] const rtl::BuiltPlugin& plugin() const { return m_plugin; }

private:
    void on_edge(std::int64_t n);
    [[nodiscard]] SpiNets nets(bool before) const;

    const SpiFpgaConfig m_cfg;
    const ClockGrid m_clock;
    const rtl::PluginSpec m_spec;
    const rtl::BuiltPlugin m_plugin;
    ObservedSpiRecords m_records;
    RtlLoop m_loop;
};

}  // namespace cnc::fpga
