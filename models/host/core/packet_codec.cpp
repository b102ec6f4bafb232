#include "host/core/packet_codec.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "common/bad_input.hpp"
#include "common/crc16.hpp"

namespace cnc::host {

namespace {

void put_be32(std::uint8_t* out, std::uint32_t v) {
    out[0] = static_cast<std::uint8_t>(v >> 24);
    out[1] = static_cast<std::uint8_t>(v >> 16);
    out[2] = static_cast<std::uint8_t>(v >> 8);
    out[3] = static_cast<std::uint8_t>(v);
}

std::uint32_t get_be32(const std::uint8_t* in) {
    return (std::uint32_t{in[0]} << 24) | (std::uint32_t{in[1]} << 16) | (std::uint32_t{in[2]} << 8) | in[3];
}

// Two's complement both ways without implementation-defined narrowing of out-of-range unsigned values.
std::uint32_t to_twos(std::int32_t v) {
    return static_cast<std::uint32_t>(v);
}
std::int32_t from_twos(std::uint32_t v) {
    return v <= 0x7FFFFFFFu ? static_cast<std::int32_t>(v)
                            : static_cast<std::int32_t>(static_cast<std::int64_t>(v) - 0x100000000LL);
}

void check_range(std::int64_t v, std::int64_t min, std::int64_t max, const std::string& where, const char* name,
                 const char* allowed) {
    if (v < min || v > max) throw BadInput(where, std::string(name) + " " + std::to_string(v) + " outside " + allowed);
}

}  // namespace

InitBytes encode_init(std::uint32_t num_x, std::uint32_t num_y) {
    InitBytes b{};
    b[0] = kInitMarker;
    put_be32(&b[1], num_x);
    put_be32(&b[5], num_y);
    return b;
}

RampInitBytes encode_ramp_init(std::uint32_t num_x, std::uint32_t num_y, std::uint32_t accel, std::uint32_t start) {
    RampInitBytes b{};
    const InitBytes seed = encode_init(num_x, num_y);
    std::copy(seed.begin(), seed.end(), b.begin());
    put_be32(&b[kInitPacketBytes], accel);
    put_be32(&b[kInitPacketBytes + 4], start);
    return b;
}

ScurveInitBytes encode_scurve_init(std::uint32_t num_x, std::uint32_t num_y, std::uint32_t accel, std::uint32_t start,
                                   std::uint32_t jerk) {
    ScurveInitBytes b{};
    const RampInitBytes ramp = encode_ramp_init(num_x, num_y, accel, start);
    std::copy(ramp.begin(), ramp.end(), b.begin());
    put_be32(&b[kRampInitPacketBytes], jerk);
    return b;
}

MotionBytes encode_motion(std::uint8_t motion, std::int32_t steps_x, std::int32_t steps_y, std::uint16_t feed) {
    if (motion == kInitMarker) throw std::invalid_argument("motion byte 0xFF would start an init packet");
    MotionBytes b{};
    b[0] = motion;
    put_be32(&b[1], to_twos(steps_x));
    put_be32(&b[5], to_twos(steps_y));
    b[9] = static_cast<std::uint8_t>(feed >> 8);
    b[10] = static_cast<std::uint8_t>(feed);
    return b;
}

MotionBytes encode_motion(const MotionPacket& p) {
    return encode_motion(p.motion, p.steps_x, p.steps_y, p.feed);
}

InitPacket decode_init(const InitBytes& b) {
    if (b[0] != kInitMarker) throw std::invalid_argument("init packet must start with 0xFF");
    return InitPacket{get_be32(&b[1]), get_be32(&b[5])};
}

MotionPacket decode_motion(const MotionBytes& b) {
    if (b[0] == kInitMarker) throw std::invalid_argument("a packet starting with 0xFF is an init packet");
    return MotionPacket{b[0], from_twos(get_be32(&b[1])), from_twos(get_be32(&b[5])),
                        static_cast<std::uint16_t>((b[9] << 8) | b[10])};
}

MotionPacket to_packet(const MotionSegment& s) {
    const std::string where = "segment " + std::to_string(s.index);
    const auto motion = static_cast<std::int64_t>(s.motion);
    check_range(motion, 0, 3, where, "motion", "0..3");
    check_range(s.steps_x, -2147483648LL, 2147483647LL, where, "steps_x", "int32 (-2147483648..2147483647)");
    check_range(s.steps_y, -2147483648LL, 2147483647LL, where, "steps_y", "int32 (-2147483648..2147483647)");
    check_range(s.feed, 0, 65535, where, "feed", "0..65535 mm/min");  // seed 000 §4.8: uint16
    return MotionPacket{static_cast<std::uint8_t>(motion), static_cast<std::int32_t>(s.steps_x),
                        static_cast<std::int32_t>(s.steps_y), static_cast<std::uint16_t>(s.feed)};
}

std::vector<std::uint8_t> motion_frame(const MotionBytes& bytes, std::optional<std::uint16_t> laser_high) {
    std::vector<std::uint8_t> out(bytes.begin(), bytes.end());
    if (laser_high) {
        out.push_back(static_cast<std::uint8_t>(*laser_high >> 8U));
        out.push_back(static_cast<std::uint8_t>(*laser_high & 0xFFU));
    }
    return out;
}

std::vector<std::uint8_t> with_crc(const std::uint8_t* bytes, std::size_t n) {
    std::vector<std::uint8_t> out(bytes, bytes + n);
    const std::uint16_t crc = crc16(bytes, n);
    out.push_back(static_cast<std::uint8_t>(crc >> 8U));
    out.push_back(static_cast<std::uint8_t>(crc & 0xFFU));
    return out;
}

}  // namespace cnc::host
