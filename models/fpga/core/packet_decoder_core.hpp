// packet_decoder (Π.4) byte state machine without timing: the byte counter is the state, the first byte picks
// the packet type (0xFF -> 9-byte init, else 11-byte motion), fields are big-endian. The module adds the clock
// edges and the 100 ms watchdog.
//
// With the packet check (protocol.crc = "crc16", our option on seed 000 §7.2's proposal of a CRC field) every packet
// carries its CRC-16/CCITT-FALSE after it, high byte first (11-byte init, 13-byte motion), and bit 7 of a motion
// packet's first byte alternates from one new move to the next (an alternating-bit protocol): a packet whose CRC
// does not leave the register at zero completes as BadCrc (the FPGA answers NAK), a good motion packet whose
// sequence bit equals the last one passed on completes as Repeat (the host sent it again because it lost the ACK:
// the move is not run twice). With the packet queue (fpga.queue_depth) the queue's packet numbers do that instead:
// no alternating bit. With the laser's PWM (fpga.laser_pwm) a motion packet has two more bytes after FeedRate, the
// PWM high time in clocks (big-endian; core/laser_pwm.hpp), before the CRC.
#pragma once
#include <array>
#include <cstdint>
#include <optional>

namespace cnc::fpga {

struct MotionFields {
    std::uint8_t motion = 0;  // b0[1:0]
    std::int32_t steps_x = 0;
    std::int32_t steps_y = 0;
    std::uint16_t feed = 0;
    std::uint8_t seq = 0;  // b0[6:2]: the packet's number with the packet queue (common/queue_protocol.hpp)
    std::uint16_t laser_high = 0;  // with fpga.laser_pwm: the PWM high time in clocks, after FeedRate
};

struct InitFields {
    std::uint32_t num_x = 0;
    std::uint32_t num_y = 0;
    std::uint32_t ramp_accel = 0;  // with the ramp (fpga.ramp): its registers, after the numerators
    std::uint32_t ramp_start = 0;
    std::uint32_t ramp_jerk = 0;  // with the S-curve
};

// With the ramp the init packet carries its registers (fpga/core/step_ramp.hpp) after the numerators; these are
// their reset values.
struct RampDefaults {
    std::uint32_t accel = 0;
    std::uint32_t start = 0;
    std::optional<std::uint32_t> jerk;  // the S-curve's: its init packet carries it too
};

class PacketDecoderCore {
public:
    enum class Completed { None, Motion, Init, BadCrc, Repeat };
    static constexpr std::uint8_t kCfgMarker = 0xFF;  // seed 000 §4.6 (Π.4 CFG_MARKER)
    static constexpr int kInitBytes = 9;              // seed 000 §4.6
    static constexpr int kRampInitBytes = 17;         // and the ramp's two 32-bit registers
    static constexpr int kScurveInitBytes = 21;       // and the S-curve's jerk
    static constexpr int kMotionBytes = 11;
    static constexpr int kLaserHighBytes = 2;           // with the laser's PWM
    static constexpr int kCrcBytes = 2;                 // with the packet check
    static constexpr std::uint8_t kSequenceBit = 0x80;  // b0[7] of a motion packet, with the packet check

    explicit PacketDecoderCore(std::uint32_t numerator_default, bool packet_crc = false, bool alternating_bit = true,
                               std::optional<RampDefaults> ramp = std::nullopt, bool laser_pwm = false)
        : m_crc(packet_crc),
          m_alternating(packet_crc && alternating_bit),
          m_ramp(ramp.has_value()),
          m_scurve(ramp && ramp->jerk),
          m_laser_pwm(laser_pwm),
          m_init{numerator_default, numerator_default, ramp ? ramp->accel : 0, ramp ? ramp->start : 0,
                 ramp ? ramp->jerk.value_or(0) : 0} {}

    // The rx_valid branch of the always block.
    Completed on_byte(std::uint8_t byte);
    // The watchdog branch (timeout_cnt reached TIMEOUT_CYCLES-1 without a byte).
    void on_timeout();

    [[nodiscard]] bool timeout_active() const { return m_timeout_active; }
    [[nodiscard]] int byte_count() const { return m_byte_count; }
    [[nodiscard]] const MotionFields& motion() const { return m_motion; }  // registered outputs: last values
    [[nodiscard]] const InitFields& init() const { return m_init; }

private:
    Completed complete_checked(bool was_cfg, std::uint8_t byte);
    void restart();
    void latch_init();
    [[nodiscard]] int init_bytes() const { return m_scurve ? kScurveInitBytes : m_ramp ? kRampInitBytes : kInitBytes; }
    [[nodiscard]] int motion_bytes() const { return m_laser_pwm ? kMotionBytes + kLaserHighBytes : kMotionBytes; }
    [[nodiscard]] MotionFields motion_fields() const;

    bool m_crc;
    bool m_alternating;
    bool m_ramp;
    bool m_scurve;
    bool m_laser_pwm;
    int m_byte_count = 0;
    bool m_timeout_active = false;
    bool m_is_cfg = false;
    std::array<std::uint8_t, kScurveInitBytes + kCrcBytes> m_bank{};  // the packet's bytes so far
    std::uint16_t m_crc_reg = 0;            // over the packet's bytes so far (with the packet check)
    bool m_sequence_seen = false;           // a motion packet has been passed on since reset
    bool m_last_sequence = false;
    MotionFields m_motion;
    InitFields m_init;
};

}  // namespace cnc::fpga
