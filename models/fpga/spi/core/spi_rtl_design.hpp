// Which Verilog runs as seed 004's FPGA when fpga.model = "rtl": ours (rtl/spi_fpga_top.v and its blocks) or the
// user's top with its sources, with the top's parameters set from the fpga_spi keys and any the user overrides.
#pragma once
#include <cstddef>

#include "fpga/spi/core/spi_fpga_config.hpp"
#include "rtl/plugin_spec.hpp"

namespace cnc::fpga {

// spi_fpga_top.v's port list: clk; rst_n, sclk, mosi, ss in; miso, STEP/DIR/nENBL per axis and laser out.
inline constexpr int kSpiRtlInResetN = 0, kSpiRtlInSclk = 1, kSpiRtlInMosi = 2, kSpiRtlInSs = 3;
inline constexpr int kSpiRtlOutMiso = 0, kSpiRtlOutStepX = 1, kSpiRtlOutDirX = 2, kSpiRtlOutEnX = 3,
                     kSpiRtlOutStepY = 4, kSpiRtlOutDirY = 5, kSpiRtlOutEnY = 6, kSpiRtlOutLaser = 7;

// The nets ObservedSpiRecords reads, in spec.observed's order. The combinational ones (ss_fell, ss_rose,
// accepted, fifo_full, rd, the FIFO's read words) read after edge n tell what edge n + 1 does.
enum SpiRtlNet : std::size_t {
    kSpiNetSsFell,     // spi_slave: FrameStart at the next edge
    kSpiNetSsRose,     // spi_slave: FrameEnd at the next edge
    kSpiNetAccepted,   // spi_slave: the frame shifted in so far is whole, with the rates command
    kSpiNetFifoFull,   // spi_slave: cmd_fifo's level as the slave sees it
    kSpiNetFifoLevel,  // top: cmd_fifo's level register
    kSpiNetRdX,        // top: pulse_gen_x loads the FIFO's word at the next edge
    kSpiNetRdY,
    kSpiNetWordDirX,  // top: the word at pulse_gen_x's FIFO read port
    kSpiNetWordPeriodX,
    kSpiNetWordDirY,
    kSpiNetWordPeriodY,
    kSpiNetPeriodX,  // pulse_gen_x: the governing period, stretched
    kSpiNetPeriodY,
    kSpiNetCountX,  // top: the step counters' registers
    kSpiNetCountY,
    // cmd_fifo's read indices and per-axis counts, read by no record: every read changes one of them, so that the
    // model stops at each read edge (two stop words in a row leave the read port, rd and the period as they were).
    kSpiNetReadIndexX,
    kSpiNetReadIndexY,
    kSpiNetAvailX,
    kSpiNetAvailY,
    // pulse_gen's scheduled rise and DIR change: with both clear, the FIFO empty and STEP low the design changes no
    // output until SPI frames come (RtlLoop::at_rest_when).
    kSpiNetRunningX,
    kSpiNetRunningY,
    kSpiNetDirPendX,
    kSpiNetDirPendY
};

// The plug-in to build: the design's sources, its top module (ours: spi_fpga_top), the parameters from `cfg`
// (FIFO_DEPTH, PULSE_CYCLES, DIR_SETUP, DIR_HOLD, IMMEDIATE; of a user's top, those it declares) then the design's
// own, and the nets above.
[[nodiscard]] rtl::PluginSpec spi_rtl_plugin_spec(const SpiFpgaConfig& cfg, const rtl::Design& design);

}  // namespace cnc::fpga
