// UART packets of seed 000 §4.5-§4.9 (T3.6, T4.6-4.9): 9-byte init (0xFF, NUMERATOR_X, NUMERATOR_Y) and 11-byte
// motion (motion, StepsX, StepsY, FeedRate), big-endian, two's complement, as Python's struct ">BII" / ">BiiH".
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "common/link_bytes.hpp"
#include "host/core/cam.hpp"

namespace cnc::host {

inline constexpr std::uint8_t kInitMarker = 0xFF;  // seed 000 §4.5: first byte 0xFF = init packet
// With the packet check (protocol.crc = "crc16", our option on seed 000 §7.2; the FPGA's NAK is in
// common/link_bytes.hpp): bit 7 of a motion packet's first byte alternates between new moves; every packet is
// followed by its CRC-16/CCITT-FALSE, high byte first (common/crc16.hpp).
inline constexpr std::uint8_t kSequenceBit = 0x80;
inline constexpr std::size_t kCrcBytes = 2;
inline constexpr std::size_t kInitPacketBytes = 9;     // seed 000 T3.6
inline constexpr std::size_t kMotionPacketBytes = 11;  // seed 000 T3.6

// With the FPGA's trapezoidal ramp (fpga.ramp, our option on seed 000 §7.2) the init packet carries the ramp's
// acceleration and start registers after the numerators (fpga/core/step_ramp.hpp has their fixed point).
inline constexpr std::size_t kRampInitPacketBytes = 17;
// With the S-curve (fpga.ramp = "s-curve") the jerk register follows (2^-80 steps per clock^3).
inline constexpr std::size_t kScurveInitPacketBytes = 21;

// With the laser's PWM (fpga.laser_pwm, our option on seed 000 §7.2's PWM laser power) a motion packet carries the
// PWM high time in clocks after FeedRate, big-endian, before any CRC (fpga/core/laser_pwm.hpp).
inline constexpr std::size_t kLaserHighBytes = 2;

using InitBytes = std::array<std::uint8_t, kInitPacketBytes>;
using RampInitBytes = std::array<std::uint8_t, kRampInitPacketBytes>;
using ScurveInitBytes = std::array<std::uint8_t, kScurveInitPacketBytes>;
using MotionBytes = std::array<std::uint8_t, kMotionPacketBytes>;

struct InitPacket {
    std::uint32_t num_x = 0;
    std::uint32_t num_y = 0;
};

struct MotionPacket {
    std::uint8_t motion = 0;  // 0..3 in practice; the FPGA uses bits [1:0]
    std::int32_t steps_x = 0;
    std::int32_t steps_y = 0;
    std::uint16_t feed = 0;  // dominant-axis feed, mm/min
};

InitBytes encode_init(std::uint32_t num_x, std::uint32_t num_y);
RampInitBytes encode_ramp_init(std::uint32_t num_x, std::uint32_t num_y, std::uint32_t accel, std::uint32_t start);
ScurveInitBytes encode_scurve_init(std::uint32_t num_x, std::uint32_t num_y, std::uint32_t accel, std::uint32_t start,
                                   std::uint32_t jerk);
// std::invalid_argument for motion 0xFF: the decoder would take the packet for an init packet.
MotionBytes encode_motion(std::uint8_t motion, std::int32_t steps_x, std::int32_t steps_y, std::uint16_t feed);
MotionBytes encode_motion(const MotionPacket& packet);
// std::invalid_argument if byte 0 is not the 0xFF marker.
InitPacket decode_init(const InitBytes& bytes);
// std::invalid_argument if byte 0 is 0xFF (that starts an init packet).
MotionPacket decode_motion(const MotionBytes& bytes);

// A motion packet as it goes on the wire before any CRC: the seed's 11 bytes, then the high time if there is one.
[[nodiscard]] std::vector<std::uint8_t> motion_frame(const MotionBytes& bytes, std::optional<std::uint16_t> laser_high);

// `bytes` followed by their CRC-16/CCITT-FALSE, high byte first.
[[nodiscard]] std::vector<std::uint8_t> with_crc(const std::uint8_t* bytes, std::size_t n);

// Range-checked conversion of a CAM / steps-file segment: cnc::BadInput("segment N", ...) if the motion is not
// 0..3, a step count is outside int32 or the feed outside 0..65535.
MotionPacket to_packet(const MotionSegment& segment);

}  // namespace cnc::host
