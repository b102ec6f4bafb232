// Timing of one SPI mode 0 transfer (CPOL = 0, CPHA = 0: SCLK idles low, both sides sample on rising edges
// and shift on falling edges, MSB first), measured from the SS falling edge t0:
//   t0                         SS falls, MOSI shows bit 0
//   t0 + cs_setup + k/SCLK     rising edge of bit k (both sides sample)
//   t0 + cs_setup + (k+1/2)/SCLK  falling edge of bit k (MOSI shows bit k+1; the slave shifts MISO)
//   t0 + transfer_time         SS rises, cs_hold after the end of the last bit cell (half a period after the
//                              last falling edge); MOSI returns low
// so transfer_time = cs_setup + bits/SCLK + cs_hold: the bits take bits/SCLK and the documented overhead is the
// two chip-select gaps. The next SS fall is at least ss_idle_min after an SS rise.
// Edge times come from integer half-period counts (cycles_to_ps), so long frames do not drift.
#pragma once
#include <cstddef>
#include <cstdint>

#include "common/units.hpp"

namespace cnc::spi {

struct SpiConfig {
    // 250 MHz / 50, a Raspberry Pi (BCM2835 core clock, even divider) rate that the FPGA's oversampling slave
    // can follow: models/fpga/spi needs SCLK < clk/6 (8.33 MHz at 50 MHz), so hm2_rpspi's 31.25 MHz default,
    // made for Mesa's SCLK-clocked slave, is out of reach here (LinuxCNC's hm2_rpspi man page).
    std::uint32_t sclk_hz = 5'000'000;
    // 1 us each: a Pi-class master's gap between its CS edge and the clock, and far above the 3 FPGA clocks
    // (60 ns) the slave needs to load its reply after seeing SS fall.
    TimePs cs_setup_ps = kPsPerUs;     // SS low -> first rising SCLK edge
    TimePs cs_hold_ps = kPsPerUs;      // end of the last bit cell -> SS high
    TimePs ss_idle_min_ps = kPsPerUs;  // SS high between two transfers
    // false: the master skips the wires (SCLK/MOSI/SS stay idle, MISO is not sampled) and exchanges the bytes
    // with the slave as one transaction at SS fall and SS rise, at the same times (models/spi/README.md).
    bool trace_wires = true;
};

// BadInput naming the key: sclk_hz in 1..100 MHz, cs_setup_ps > 0, cs_hold_ps >= 0, ss_idle_min_ps > 0.
void validate(const SpiConfig& cfg);

// SS low time of one transfer of `bits` bits: cs_setup + bits/SCLK + cs_hold.
[[nodiscard]] TimePs transfer_time_ps(const SpiConfig& cfg, std::size_t bits);
// Bus time per transfer including the minimum SS-high gap: what one servo period must hold.
[[nodiscard]] TimePs transfer_slot_ps(const SpiConfig& cfg, std::size_t bits);
// Offsets from the SS fall of the rising and falling SCLK edges of bit k (k = 0 is the first bit).
[[nodiscard]] TimePs sclk_rise_ps(const SpiConfig& cfg, std::int64_t bit);
[[nodiscard]] TimePs sclk_fall_ps(const SpiConfig& cfg, std::int64_t bit);
// Half an SCLK period (the time MISO has between the slave's shift and the master's sample), rounded down.
[[nodiscard]] TimePs sclk_half_period_ps(const SpiConfig& cfg);

// BadInput ("spi: sclk_hz") when one transfer slot does not fit in the servo period: the message gives the
// frame bits, the transfer and slot times and the period.
void check_transfer_fits(const SpiConfig& cfg, std::size_t bits, TimePs servo_period_ps);

}  // namespace cnc::spi
