// spi_slave (seed 004 §5.1.1: mode 0 slave; SS active low, §5.2) over core/spi_slave_core.hpp. On the wires it
// wakes once per pin change to sample the pins at the next FPGA clock edge, and once per logic action 2 edges later:
//   FrameStart: the reply is built from the FIFO status and the step counters as loaded at that edge
//               (counters count STEP rises at edges <= FrameStart - 2) and bit 0 goes out on MISO;
//   MisoShift:  the next reply bit goes out on MISO;
//   FrameEnd:   a frame of exactly frame_bits(n_axes) bits with the kCmdRates header is pushed to the FIFO at
//               that edge (dropped if full); any other frame is rejected and counted. MISO returns low.
// As a SpiSlaveIf (the master's fast path) the same actions happen at the same edges, without the wires.
// Sticky status flags (dropped, rejected) report events since the previous reply.
#pragma once
#include <cstddef>
#include <cstdint>
#include <systemc>
#include <vector>

#include "fpga/spi/cmd_fifo.hpp"
#include "fpga/spi/core/spi_fpga_records.hpp"
#include "fpga/spi/core/spi_slave_core.hpp"
#include "fpga/spi/step_counter.hpp"
#include "fpga/timed_writer.hpp"
#include "spi/spi_slave_if.hpp"

namespace cnc::fpga {

class SpiSlave : public sc_core::sc_module, public spi::SpiSlaveIf {
public:
    sc_core::sc_in<bool> sclk;
    sc_core::sc_in<bool> mosi;
    sc_core::sc_in<bool> ss;
    sc_core::sc_out<bool> miso;
    sc_core::sc_port<CmdFifoWriteIf> fifo;
    sc_core::sc_port<StepCountIf, 0> counters;  // bound in axis order, n_axes of them

    SpiSlave(const sc_core::sc_module_name& name, const SpiFpgaConfig& cfg, std::size_t n_axes);

    void select(TimePs t_ss_fall_ps) override;
    void deselect(TimePs t_ss_rise_ps, const std::vector<std::uint8_t>& mosi_bytes,
                  std::vector<std::uint8_t>& miso_bytes) override;

    // The frame log (a record per frame, with its reply bytes) is for tests and benches; a system turns it off
    // before the simulation, so that memory does not grow with a long job's frames, and keeps the counts.
    void keep_frame_log(bool on) { m_keep_frame_log = on; }
    [[nodiscard]] const std::vector<SlaveFrameRecord>& frames() const { return m_frames; }
    [[nodiscard]] std::uint64_t frame_count() const { return m_frame_count; }  // frames started
    // Frames handed to the FIFO (pushed, or dropped there when full); the others were rejected or never ended.
    [[nodiscard]] std::uint64_t accepted_count() const { return m_accepted_count; }
    [[nodiscard]] std::uint64_t rejected() const { return m_rejected; }
    [[nodiscard]] std::uint64_t activations() const;

private:
    void end_of_elaboration() override;
    void on_pin_change();
    void on_sample();
    void act(const SlaveEvent& e, bool wires);
    void frame_start(std::int64_t edge, bool wires);
    void frame_end(const SlaveEvent& e, bool wires);
    [[nodiscard]] bool reply_bit(std::size_t k) const;

    const std::size_t m_axes;
    const ClockGrid m_clock;
    SpiSlaveCore m_core;
    TimedWriter m_writer;
    sc_core::sc_event m_sample;
    std::vector<SlaveEvent> m_events;  // scratch
    std::vector<std::uint8_t> m_reply;
    std::int64_t m_reply_edge = -1;
    std::int64_t m_select_edge = -1;  // FrameStart edge of the transaction in progress
    std::uint64_t m_rejected = 0;
    std::uint64_t m_rejected_reported = 0;
    std::uint64_t m_drops_reported = 0;
    bool m_keep_frame_log = true;
    std::vector<SlaveFrameRecord> m_frames;
    SlaveFrameRecord m_frame;  // the frame in progress, without the log
    std::uint64_t m_frame_count = 0;
    std::uint64_t m_accepted_count = 0;
    std::uint64_t m_activations = 0;
};

}  // namespace cnc::fpga
