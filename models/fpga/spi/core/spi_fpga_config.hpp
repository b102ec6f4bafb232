// Parameters of the spi-fpga FPGA design (seed 004 §5.1; the thesis's iCE40 design extended to two axes with
// step counters), the link constraints of its oversampling SPI slave, and the shortest STEP period.
#pragma once
#include <cstdint>

#include "common/clock_grid.hpp"
#include "common/units.hpp"
#include "spi/core/spi_timing.hpp"

namespace cnc::fpga {

// When a rate word read from the FIFO governs the generator (the seed 004 thesis does not say).
//  AtNextPulse: a running generator reads the FIFO only at the edge where its running period ends (its next
//               STEP rise); a stopped one reads at once. The new period starts at that edge.
//  Immediately: the generator reads an entry one clock after it is written; the period counter compares
//               against the new period at once (the next rise is max(read edge, last rise + new period)).
enum class RateApply { AtNextPulse, Immediately };

struct SpiFpgaConfig {
    std::uint32_t clk_hz = 50'000'000;    // 50 MHz, as seed 000's board
    std::uint32_t fifo_depth = 4;         // frames between the SPI slave and the generators
    std::uint32_t pulse_cycles = 100;     // seed 004 §5.1.3 `duration`; 100 clocks = 2 us (seed 000 PULSE_HIGH)
    std::uint32_t dir_setup_cycles = 50;  // 1 us from a DIR change to the next STEP rise (DRV8825: 650 ns)
    std::uint32_t dir_hold_cycles = 50;   // 1 us from a STEP rise to a DIR change (DRV8825: 650 ns)
    RateApply rate_apply = RateApply::AtNextPulse;
    ClockDeviation clock;  // the board oscillator's offset and jitter (all zero: an ideal clock)
};

// The logic sees a pin level kSpiSyncStages edges after the first flip-flop samples it (2-FF synchroniser,
// the edge detector's third register compares stage 2 with its previous value in the same clock).
inline constexpr std::int64_t kSpiSyncStages = 2;

// The nominal clock period, for the link's design-time margins (a few ppm of offset do not move them).
[[nodiscard]] TimePs clock_period_ps(const SpiFpgaConfig& cfg);
// The edges of the FPGA's clock: clk_hz as this board's oscillator makes it.
[[nodiscard]] ClockGrid clock_grid(const SpiFpgaConfig& cfg);
// Shortest STEP period: the pulse plus one low clock. Shorter words are stretched to it (and counted).
[[nodiscard]] constexpr std::uint32_t min_period_cycles(const SpiFpgaConfig& cfg) {
    return cfg.pulse_cycles + 1;
}

// BadInput naming the key: clk_hz must divide 1e12; depth >= 1; pulse, setup and hold >= 1 clock (with 0, a
// DIR change could share an edge with a STEP rise and the counter would read the wrong direction).
void validate(const SpiFpgaConfig& cfg);

// What the oversampling slave needs from the master, worst case over the phase between the two clocks (a pin
// change is seen by the logic at most 3 clocks later: up to one clock to the first sample + 2 stages):
//  half an SCLK period > 3 clocks (MISO, shifted after a falling edge, must be out before the next rising
//  edge; this also covers MOSI, sampled <= 1 clock after a rising edge), cs_setup > 3 clocks (bit 0 of the
//  reply must be out before the first rising edge), ss_idle_min >= 1 clock (SS high must be sampled).
// BadInput ("spi: sclk_hz", ...) with the limit in the message.
void check_link(const spi::SpiConfig& link, const SpiFpgaConfig& cfg);
// Highest SCLK rate check_link accepts.
[[nodiscard]] std::uint32_t max_sclk_hz(const SpiFpgaConfig& cfg);

}  // namespace cnc::fpga
