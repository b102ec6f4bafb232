#include "uart/core/uart_frame.hpp"

#include <string>

#include "common/bad_input.hpp"

namespace cnc::uart {

void validate(const FrameFormat& fmt) {
    if (fmt.data_bits < 5 || fmt.data_bits > 8)
        throw BadInput("", "UART data bits must be 5..8 (got " + std::to_string(fmt.data_bits) + ")");
    if (fmt.stop_bits < 1 || fmt.stop_bits > 2)
        throw BadInput("", "UART stop bits must be 1 or 2 (got " + std::to_string(fmt.stop_bits) + ")");
}

std::vector<bool> frame_bits(std::uint8_t byte, const FrameFormat& fmt) {
    validate(fmt);
    std::vector<bool> bits;
    bits.reserve(static_cast<std::size_t>(fmt.bits_per_frame()));
    bits.push_back(false);  // start bit
    int ones = 0;
    for (int i = 0; i < fmt.data_bits; ++i) {
        const bool b = ((byte >> i) & 1U) != 0;
        ones += b ? 1 : 0;
        bits.push_back(b);
    }
    if (fmt.parity != Parity::None) {
        const bool odd_ones = (ones % 2) != 0;
        bits.push_back(fmt.parity == Parity::Even ? odd_ones : !odd_ones);
    }
    for (int i = 0; i < fmt.stop_bits; ++i) bits.push_back(true);
    return bits;
}

std::vector<Edge> frame_edges(std::uint8_t byte, TimePs t_start_ps, BitClock clk, const FrameFormat& fmt) {
    const std::vector<bool> bits = frame_bits(byte, fmt);
    std::vector<Edge> edges;
    bool level = true;  // idle line
    for (std::size_t k = 0; k < bits.size(); ++k) {
        if (bits[k] == level) continue;
        level = bits[k];
        edges.push_back({t_start_ps + clk.bit_edge(static_cast<std::int64_t>(k)), level});
    }
    return edges;
}

TimePs frame_time_ps(BitClock clk, const FrameFormat& fmt) {
    return clk.bit_edge(fmt.bits_per_frame());
}

}  // namespace cnc::uart
