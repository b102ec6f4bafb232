// packet_decoder (Π.4) byte state machine without timing: the byte counter is the state, the first byte picks
// the packet type (0xFF -> 9-byte init, else 11-byte motion), fields are big-endian. The module adds the clock
// edges and the 100 ms watchdog.
#pragma once
#include <array>
#include <cstdint>

namespace cnc::fpga {

struct MotionFields {
    std::uint8_t motion = 0;  // b0[1:0]
    std::int32_t steps_x = 0;
    std::int32_t steps_y = 0;
    std::uint16_t feed = 0;
};

struct InitFields {
    std::uint32_t num_x = 0;
    std::uint32_t num_y = 0;
};

class PacketDecoderCore {
public:
    enum class Completed { None, Motion, Init };
    static constexpr std::uint8_t kCfgMarker = 0xFF;  // seed 000 §4.6 (Π.4 CFG_MARKER)
    static constexpr int kInitBytes = 9;              // seed 000 §4.6
    static constexpr int kMotionBytes = 11;

    explicit PacketDecoderCore(std::uint32_t numerator_default) : m_init{numerator_default, numerator_default} {}

    // The rx_valid branch of the always block.
    Completed on_byte(std::uint8_t byte);
    // The watchdog branch (timeout_cnt reached TIMEOUT_CYCLES-1 without a byte).
    void on_timeout();

    [[nodiscard]] bool timeout_active() const { return m_timeout_active; }
    [[nodiscard]] int byte_count() const { return m_byte_count; }
    [[nodiscard]] const MotionFields& motion() const { return m_motion; }  // registered outputs: last values
    [[nodiscard]] const InitFields& init() const { return m_init; }

private:
    int m_byte_count = 0;
    bool m_timeout_active = false;
    bool m_is_cfg = false;
    std::array<std::uint8_t, 10> m_bank{};  // b0..b9 (the 11th motion / 9th init byte is used live)
    MotionFields m_motion;
    InitFields m_init;
};

}  // namespace cnc::fpga
