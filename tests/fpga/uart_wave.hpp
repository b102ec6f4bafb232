// Test-only UART transmitter: builds the rx line of the FPGA as a list of level changes (idle high), 8N1, LSB
// first, bit boundaries on the sender's own clock (50 MHz / 434 like the FPGA, or the CP2102's 24 MHz / 208).
#pragma once
#include <cstdint>
#include <vector>

#include "common/edge_log.hpp"
#include "common/units.hpp"

namespace cnc::fpga::test {

class UartWave {
public:
    UartWave(std::int64_t tick_hz, std::int64_t ticks_per_bit) : m_tick_hz(tick_hz), m_ticks_per_bit(ticks_per_bit) {}

    // One frame whose start bit falls at t_ps; returns the end of its stop bit. A bad stop bit is driven low.
    TimePs byte(TimePs t_ps, std::uint8_t value, bool good_stop = true);
    // Back-to-back frames from t_ps; returns the end of the last stop bit.
    TimePs bytes(TimePs t_ps, const std::vector<std::uint8_t>& values);
    // A low pulse [t_ps, t_ps + width_ps) on the idle line.
    void glitch(TimePs t_ps, TimePs width_ps);
    // Start-bit time of every frame sent so far.
    [[nodiscard]] const std::vector<TimePs>& frame_starts() const { return m_frame_starts; }
    [[nodiscard]] const std::vector<Edge>& changes() const { return m_changes; }

private:
    [[nodiscard]] TimePs bit_boundary(TimePs t0, std::int64_t bit) const {
        return t0 + cycles_to_ps(bit * m_ticks_per_bit, m_tick_hz);
    }
    void drive(TimePs t_ps, bool level);

    std::int64_t m_tick_hz;
    std::int64_t m_ticks_per_bit;
    std::vector<Edge> m_changes;
    std::vector<TimePs> m_frame_starts;
    bool m_level = true;
};

// Seed 000 §4.5-§4.9 packets, big-endian.
std::vector<std::uint8_t> init_packet(std::uint32_t num_x, std::uint32_t num_y);
std::vector<std::uint8_t> motion_packet(std::uint8_t motion, std::int32_t steps_x, std::int32_t steps_y,
                                        std::uint16_t feed);

}  // namespace cnc::fpga::test
