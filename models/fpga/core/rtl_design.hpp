// Which Verilog runs as seed 000's FPGA when fpga.model = "rtl": ours (rtl/top.v and its blocks) or the user's
// top with its sources, with the top's parameters set from the FPGA's scenario keys and any the user overrides.
#pragma once
#include "fpga/core/fpga_config.hpp"
#include "rtl/plugin_spec.hpp"

namespace cnc::fpga {

// Our top's port list (README of rtl/): clk; rst_n, rx, estop and lid_open in; tx, DIR/STEP/nENBL per axis, laser
// and busy out.
inline constexpr int kRtlOutTx = 0, kRtlOutDirX = 1, kRtlOutStepX = 2, kRtlOutEnX = 3, kRtlOutDirY = 4,
                     kRtlOutStepY = 5, kRtlOutEnY = 6, kRtlOutLaser = 7, kRtlOutBusy = 8;
inline constexpr int kRtlInResetN = 0, kRtlInRx = 1, kRtlInEstop = 2, kRtlInLidOpen = 3;

// step_ramp.v divides the ramp's cruise velocity during DIR_WAIT: its registers are ready 52 clocks into it (with
// step_gen's single-clock periods).
inline constexpr std::uint32_t kRtlRampDirSettleMin = 52;

// The plug-in to build: the design's sources, its top module (the one named as the file, our "top"), the
// parameters from `cfg` (CLK_HZ, FULL_BIT, PULSE_HIGH, DIR_SETTLE, FEED_ZERO_PERIOD, TIMEOUT_CYCLES,
// NUMERATOR_DEFAULT, EXACT_PERIOD, INIT_WIRED, PACKET_CRC, LASER_PWM_PERIOD, ESTOP, INTERLOCK, RAMP,
// RAMP_ACCEL_DEFAULT, RAMP_START_DEFAULT, QUEUE_DEPTH; of a user's top, those it declares) then the design's own,
// and the nets ObservedRecords reads (the packet check's, the e-stop's and the queue's only with them; with the queue
// the moves are its outputs to step_gen, not the decoder's). estop and lid_open are required of a
// user's top only with their options.
[[nodiscard]] rtl::PluginSpec rtl_plugin_spec(const FpgaConfig& cfg, const rtl::Design& design);

}  // namespace cnc::fpga
