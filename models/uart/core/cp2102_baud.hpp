// The baud rate a CP2102 really produces for a requested rate.
//
// Two stages, both documented by Silicon Labs:
//  1. AN205 "CP210x Baud Rate Support" Table 1 (CP2101/2/3 default configuration): the chip maps any requested
//     rate to one of 32 fixed UART rates by range (e.g. 77609..117028 -> 115200). Requests outside every range
//     are not supported (BadInput).
//  2. The UART bit clock divides the chip's 24 MHz clock by an integer (AN205 baud rate reload values; the
//     CP210x-family "Clock Divider = 24 MHz / (2 x Prescale x Baud)" data-sheet equation): divider =
//     round(24 MHz / rate), actual = 24 MHz / divider. 115200 -> 208 -> 115 384.6 Bd (+0.16 %);
//     57600 -> 417 -> 57 553.96 Bd (-0.08 %). `divider` here is the total number of 24 MHz clocks per bit
//     (prescale x reload count), which is what the line timing needs; at 300 Bd the chip uses prescale 4, which
//     gives the same 80 000 clocks per bit.
#pragma once
#include <cstdint>

#include "uart/core/uart_frame.hpp"

namespace cnc::uart {

inline constexpr std::int64_t kCp2102ClockHz = 24'000'000;  // AN205 §2: 24 MHz baud rate generator clock

struct Cp2102Baud {
    std::uint32_t requested = 0;
    std::uint32_t table_rate = 0;  // AN205 Table 1 rate (the requested rate itself when ideal)
    std::int64_t divider = 0;      // clocks of clk_hz per bit
    std::int64_t clk_hz = kCp2102ClockHz;
    double actual_bd = 0.0;
    double error_pct = 0.0;  // actual against REQUESTED: what the far end, set to the requested rate, sees

    [[nodiscard]] BitClock bit_clock() const { return {divider, clk_hz}; }
};

// AN205 Table 1 lookup; BadInput for a rate outside every range.
[[nodiscard]] std::uint32_t cp2102_table_rate(std::uint32_t requested);

// ideal = true: the line runs at exactly the requested rate (any rate > 0): the bit clock is then one tick
// of a `requested` Hz clock, so every bit boundary is the exact time rounded down to the picosecond, without
// drift.
[[nodiscard]] Cp2102Baud cp2102_baud(std::uint32_t requested, bool ideal = false);

}  // namespace cnc::uart
