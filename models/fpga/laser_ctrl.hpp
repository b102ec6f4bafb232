// laser_ctrl (seed 000 §5.2.5, Π.6 "fixed version"): engrave latched from motion on every pkt_valid (even one
// step_gen ignores because it is busy), laser <= engrave & busy one clock later; with our interlock input
// (fpga.interlock) laser <= engrave & busy & !inhibit. With our PWM (fpga.laser_pwm, core/laser_pwm.hpp) the packet's
// high time is latched with engrave, the PWM count restarts there and counts while busy, and the pin is also gated by
// count < high: the pin's edges are scheduled at the count's turns, never clocked through.
#pragma once
#include <cstdint>
#include <systemc>

#include "fpga/core/fpga_config.hpp"
#include "fpga/timed_writer.hpp"

namespace cnc::fpga {

class LaserCtrl : public sc_core::sc_module {
public:
    sc_core::sc_in<std::uint8_t> motion;
    sc_core::sc_in<std::uint16_t> laser_high;  // the packet's PWM high time (read with fpga.laser_pwm only)
    sc_core::sc_in<bool> pkt_valid;
    sc_core::sc_in<bool> busy;
    sc_core::sc_in<bool> inhibit;  // the synchronised lid input (tied low without the interlock)
    sc_core::sc_out<bool> laser;

    LaserCtrl(const sc_core::sc_module_name& name, const FpgaConfig& cfg);
    void add_traces(sc_core::sc_trace_file* tf) const;
    [[nodiscard]] std::uint64_t activations() const { return m_activations + m_writer.activations(); }

private:
    void on_inputs();
    void on_pwm_turn();
    // The registers as they are after edge `edge` give the pin at edge + 1.
    void drive(std::int64_t edge);

    const ClockGrid m_clock;
    const std::uint32_t m_pwm_period;                      // clocks; 0: the seed's on/off laser
    sc_core::sc_signal<bool> m_engrave{"engrave", false};  // register, reset 0 (laser safe OFF)
    std::uint16_t m_high = 0;                              // register latched with engrave
    std::int64_t m_count_zero_edge = 0;  // the edge after which the PWM count was 0 (busy has been high since)
    sc_core::sc_event m_pwm_turn;
    TimedWriter m_writer;
    std::uint64_t m_activations = 0;
};

}  // namespace cnc::fpga
