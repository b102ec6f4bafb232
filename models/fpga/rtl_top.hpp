// Seed 000's FPGA as Verilog (ours in rtl/, or the user's) verilated and clocked in the loop (rtl_loop.hpp): its
// batches run up to the time before which rx cannot change (what the CP2102 has promised: rx_quiet_until). The
// records come from the design's own nets (ObservedRecords), or from its busy and tx pins when it lacks them.
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <systemc>
#include <utility>
#include <vector>

#include "fpga/board.hpp"
#include "fpga/core/fpga_config.hpp"
#include "fpga/core/observed_records.hpp"
#include "fpga/core/rtl_design.hpp"
#include "fpga/rtl_loop.hpp"
#include "rtl/plugin_build.hpp"

namespace cnc::fpga {

class RtlTop final : public Board {
public:
    // Builds the plug-in (or takes it from the cache): BadInput from rtl::build_plugin.
    RtlTop(const sc_core::sc_module_name& name, const FpgaConfig& cfg, const rtl::Design& design);

    // The earliest time rx may change, asked at the current time (>= now). Until given: now (one edge a batch).
    void rx_quiet_until(std::function<TimePs()> quiet_until_ps) { m_loop.inputs_quiet_until(std::move(quiet_until_ps)); }

    [[nodiscard]] std::size_t packet_count() const override { return m_records.packet_count(); }
    [[nodiscard]] PacketRecord packet(std::size_t i) const override { return m_records.packet(i); }
    void drop_packets_before(std::size_t end) override { m_records.drop_packets_before(end); }
    [[nodiscard]] const std::vector<InitRecord>& inits() const override { return m_records.inits(); }
    [[nodiscard]] FpgaStats stats() const override { return m_records.stats(); }
    [[nodiscard]] bool records_from_nets() const override { return m_records.from_nets(); }
    [[nodiscard]] const ClockGrid& clock() const override { return m_clock; }
    // Clock edges the model has run, and how the plug-in was obtained.
    [[nodiscard]] std::int64_t cycles() const { return m_loop.cycles(); }
    [[nodiscard]] const rtl::BuiltPlugin& plugin() const { return m_plugin; }

private:
    void on_edge(std::int64_t n);

    const FpgaConfig m_cfg;
    const ClockGrid m_clock;
    const rtl::PluginSpec m_spec;
    const rtl::BuiltPlugin m_plugin;
    // With the e-stop: the observed halt and halted nets' indices in m_spec.
    const std::size_t m_halt_net;
    const std::size_t m_halted_net;
    // With the packet queue: the decoder's pkt_valid, the queue's strobes and the status's start.
    const std::size_t m_decoder_pkt_valid_net;
    const std::size_t m_queued_net;
    const std::size_t m_again_net;
    const std::size_t m_refused_net;
    const std::size_t m_status_start_net;
    ObservedRecords m_records;
    RtlLoop m_loop;
};

}  // namespace cnc::fpga
