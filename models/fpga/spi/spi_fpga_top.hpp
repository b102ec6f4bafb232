// spi_fpga_top (seed 004 §5.1 data path, plus step counters): spi_slave -> cmd_fifo -> one pulse_gen per axis, and one
// step_counter per axis reading the STEP/DIR pins back for the SPI reply. Two axes (X = axis 0, Y = axis 1).
// laser_latch drives the `laser` pin from the frames' laser bit, switching when a frame's rates all govern.
// The pins (spi_board.hpp) are for the wire path; `spi_target` is the transaction path used by SpiMaster with
// trace_wires = false. Bind ss to a signal that starts high; every output must be bound.
#pragma once
#include <cstddef>
#include <cstdint>
#include <systemc>
#include <vector>

#include "fpga/spi/cmd_fifo.hpp"
#include "fpga/spi/core/spi_fpga_config.hpp"
#include "fpga/spi/laser_latch.hpp"
#include "fpga/spi/pulse_gen.hpp"
#include "fpga/spi/spi_board.hpp"
#include "fpga/spi/spi_slave.hpp"
#include "fpga/spi/step_counter.hpp"

namespace cnc::fpga {

class SpiFpgaTop final : public SpiBoard {
public:
    sc_core::sc_export<spi::SpiSlaveIf> spi_target;

    SpiFpgaTop(const sc_core::sc_module_name& name, const SpiFpgaConfig& cfg);

    [[nodiscard]] const SpiFpgaConfig& config() const override { return m_cfg; }
    // The per-frame logs below (frames, fifo_pushes, applied_frames) are for tests and benches; a system turns them
    // off before the simulation, so that memory does not grow with a long job's frames. Counts stay (slave, fifo).
    void keep_frame_logs(bool on);
    [[nodiscard]] const std::vector<SlaveFrameRecord>& frames() const { return slave.frames(); }
    [[nodiscard]] const std::vector<FifoPushRecord>& fifo_pushes() const { return fifo.core().pushes(); }
    [[nodiscard]] const std::vector<AppliedRate>& applied(std::size_t axis) const;  // not taken yet
    [[nodiscard]] std::vector<AppliedRate> take_applied(std::size_t axis) override;
    [[nodiscard]] std::uint64_t applied_count(std::size_t axis) const;  // taken or not
    [[nodiscard]] const std::vector<AppliedFrame>& applied_frames() const { return fifo.applied(); }
    [[nodiscard]] std::int32_t count(std::size_t axis) const;  // step counter now (all updates so far)
    [[nodiscard]] SpiFpgaStats stats() const override;
    [[nodiscard]] std::uint64_t activations() const;           // every process wake (per edge, never per clock)
    void add_traces(sc_core::sc_trace_file* tf) const;

private:
    const SpiFpgaConfig m_cfg;

public:  // blocks, named as their RTL modules
    SpiSlave slave;
    CmdFifo fifo;
    PulseGen pulse_gen_x;
    PulseGen pulse_gen_y;
    StepCounter step_counter_x;
    StepCounter step_counter_y;
    LaserLatch laser_latch;
};

}  // namespace cnc::fpga
