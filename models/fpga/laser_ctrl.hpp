// laser_ctrl (seed 000 §5.2.5, Π.6 "fixed version"): engrave latched from motion on every pkt_valid (even one
// step_gen ignores because it is busy), laser <= engrave & busy one clock later; with our interlock input
// (fpga.interlock) laser <= engrave & busy & !inhibit.
#pragma once
#include <cstdint>
#include <systemc>

#include "fpga/core/fpga_config.hpp"
#include "fpga/timed_writer.hpp"

namespace cnc::fpga {

class LaserCtrl : public sc_core::sc_module {
public:
    sc_core::sc_in<std::uint8_t> motion;
    sc_core::sc_in<bool> pkt_valid;
    sc_core::sc_in<bool> busy;
    sc_core::sc_in<bool> inhibit;  // the synchronised lid input (tied low without the interlock)
    sc_core::sc_out<bool> laser;

    LaserCtrl(const sc_core::sc_module_name& name, const FpgaConfig& cfg);
    void add_traces(sc_core::sc_trace_file* tf) const;
    [[nodiscard]] std::uint64_t activations() const { return m_activations + m_writer.activations(); }

private:
    void on_inputs();

    const ClockGrid m_clock;
    sc_core::sc_signal<bool> m_engrave{"engrave", false};  // register, reset 0 (laser safe OFF)
    TimedWriter m_writer;
    std::uint64_t m_activations = 0;
};

}  // namespace cnc::fpga
