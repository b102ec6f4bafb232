#include "uart_wave.hpp"

#include <stdexcept>

namespace cnc::fpga::test {

void UartWave::drive(TimePs t_ps, bool level) {
    if (!m_changes.empty() && t_ps == m_changes.back().t_ps) {  // a later drive at the same instant wins
        m_changes.pop_back();
        m_level = m_changes.empty() ? true : m_changes.back().level;
    }
    if (level == m_level) return;
    if (!m_changes.empty() && t_ps < m_changes.back().t_ps) throw std::logic_error("UartWave: changes out of order");
    m_changes.push_back({t_ps, level});
    m_level = level;
}

TimePs UartWave::byte(TimePs t_ps, std::uint8_t value, bool good_stop) {
    m_frame_starts.push_back(t_ps);
    drive(t_ps, false);
    for (int i = 0; i < 8; ++i) drive(bit_boundary(t_ps, 1 + i), ((value >> i) & 1U) != 0);
    drive(bit_boundary(t_ps, 9), good_stop);
    const TimePs end = bit_boundary(t_ps, 10);
    drive(end, true);  // back to idle (only a bad stop bit leaves the line low until here)
    return end;
}

TimePs UartWave::bytes(TimePs t_ps, const std::vector<std::uint8_t>& values) {
    for (const std::uint8_t v : values) t_ps = byte(t_ps, v);
    return t_ps;
}

void UartWave::glitch(TimePs t_ps, TimePs width_ps) {
    drive(t_ps, false);
    drive(t_ps + width_ps, true);
}

namespace {
void put32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>(v >> shift));
}
}  // namespace

std::vector<std::uint8_t> init_packet(std::uint32_t num_x, std::uint32_t num_y) {
    std::vector<std::uint8_t> out{0xFF};
    put32(out, num_x);
    put32(out, num_y);
    return out;
}

std::vector<std::uint8_t> motion_packet(std::uint8_t motion, std::int32_t steps_x, std::int32_t steps_y,
                                        std::uint16_t feed) {
    std::vector<std::uint8_t> out{motion};
    put32(out, static_cast<std::uint32_t>(steps_x));
    put32(out, static_cast<std::uint32_t>(steps_y));
    out.push_back(static_cast<std::uint8_t>(feed >> 8));
    out.push_back(static_cast<std::uint8_t>(feed & 0xFF));
    return out;
}

}  // namespace cnc::fpga::test
