// laser_latch: the register behind the FPGA's `laser` pin (reset low: laser off). It loads the laser bit of each
// frame (bit 30 of the X rate word, models/spi/README.md) at the edge cmd_fifo reports the frame applied, i.e. when
// the last axis loads its rate word of that frame: the laser switches at the instant the frame's rates all govern
// (one clock after the FIFO write with RateApply::Immediately; with AtNextPulse at the slowest axis's boundary).
#pragma once
#include <cstdint>
#include <systemc>

#include "fpga/spi/cmd_fifo.hpp"

namespace cnc::fpga {

class LaserLatch : public sc_core::sc_module {
public:
    sc_core::sc_out<bool> laser;
    sc_core::sc_port<CmdFifoAppliedIf> fifo;

    explicit LaserLatch(const sc_core::sc_module_name& name);

    [[nodiscard]] std::uint64_t activations() const { return m_activations; }

private:
    void on_applied();

    sc_core::sc_event_finder_t<CmdFifoAppliedIf> m_applied{fifo, &CmdFifoAppliedIf::applied_event};
    std::uint64_t m_activations = 0;
};

}  // namespace cnc::fpga
