// The line waveform of one asynchronous (RS-232 style, TTL level) frame, shared by every UART transmitter
// model (CP2102, FPGA uart_tx, AVR USART): start bit low, data bits LSB first, optional parity, stop bit(s)
// high; the line idles high.
#pragma once
#include <cstdint>
#include <vector>

#include "common/edge_log.hpp"
#include "common/units.hpp"

namespace cnc::uart {

// A bit clock that divides a reference clock: one bit lasts `ticks_per_bit` periods of `clk_hz`
// (CP2102: 208 ticks of 24 MHz at 115200 Bd; seed 000 §4.2 FPGA: 434 ticks of 50 MHz).
struct BitClock {
    std::int64_t ticks_per_bit = 1;
    std::int64_t clk_hz = 1;

    // Time of bit boundary k after a frame start (k = 0 is the start edge). Each boundary is computed from
    // the tick count, not by adding rounded bit times, so there is no cumulative drift (<= 1 ps rounding).
    [[nodiscard]] TimePs bit_edge(std::int64_t k) const { return cycles_to_ps(k * ticks_per_bit, clk_hz); }
    // Middle of bit k (k + 0.5 bit), where an ideal receiver samples.
    [[nodiscard]] TimePs mid_bit(std::int64_t k) const { return cycles_to_ps((2 * k + 1) * ticks_per_bit, 2 * clk_hz); }
    [[nodiscard]] double baud() const { return static_cast<double>(clk_hz) / static_cast<double>(ticks_per_bit); }
};

enum class Parity { None, Even, Odd };

struct FrameFormat {
    int data_bits = 8;  // 5..8
    Parity parity = Parity::None;
    int stop_bits = 1;  // 1 or 2

    [[nodiscard]] int bits_per_frame() const { return 1 + data_bits + (parity == Parity::None ? 0 : 1) + stop_bits; }
};

// 8N1: seed 000 §4.2, and the format every architecture in this project uses.
inline constexpr FrameFormat kFormat8N1{};

// Throws BadInput for a format outside 5..8 data bits, 1..2 stop bits.
void validate(const FrameFormat& fmt);

// The level of each bit of the frame, bit 0 = start bit, last = final stop bit.
[[nodiscard]] std::vector<bool> frame_bits(std::uint8_t byte, const FrameFormat& fmt = kFormat8N1);

// Level CHANGES of one frame starting at t_start_ps on an idle (high) line; the line is high again at the
// end (it stays high until the next start bit, so the last change is the rise into the stop bit, if any).
[[nodiscard]] std::vector<Edge> frame_edges(std::uint8_t byte, TimePs t_start_ps, BitClock clk,
                                            const FrameFormat& fmt = kFormat8N1);

// Duration of one frame (start edge to the end of the last stop bit).
[[nodiscard]] TimePs frame_time_ps(BitClock clk, const FrameFormat& fmt = kFormat8N1);

}  // namespace cnc::uart
