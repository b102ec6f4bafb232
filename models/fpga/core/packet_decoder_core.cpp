#include "fpga/core/packet_decoder_core.hpp"

#include "common/crc16.hpp"
#include "common/queue_protocol.hpp"

namespace cnc::fpga {

namespace {
std::uint32_t be32(std::uint8_t a, std::uint8_t b, std::uint8_t c, std::uint8_t d) {
    return (std::uint32_t{a} << 24) | (std::uint32_t{b} << 16) | (std::uint32_t{c} << 8) | std::uint32_t{d};
}
}  // namespace

// The bank holds every byte of the packet by its last one.
MotionFields PacketDecoderCore::motion_fields() const {
    const auto& b = m_bank;
    return {static_cast<std::uint8_t>(b[0] & 0x3U),
            static_cast<std::int32_t>(be32(b[1], b[2], b[3], b[4])),
            static_cast<std::int32_t>(be32(b[5], b[6], b[7], b[8])),
            static_cast<std::uint16_t>((b[9] << 8) | b[10]),
            static_cast<std::uint8_t>(queue_protocol::seq_of(b[0])),
            static_cast<std::uint16_t>(m_laser_pwm ? (b[11] << 8) | b[12] : 0)};
}

void PacketDecoderCore::latch_init() {
    const auto& b = m_bank;
    m_init.num_x = be32(b[1], b[2], b[3], b[4]);
    m_init.num_y = be32(b[5], b[6], b[7], b[8]);
    if (!m_ramp) return;
    m_init.ramp_accel = be32(b[9], b[10], b[11], b[12]);
    m_init.ramp_start = be32(b[13], b[14], b[15], b[16]);
    if (m_scurve) m_init.ramp_jerk = be32(b[17], b[18], b[19], b[20]);
}

void PacketDecoderCore::restart() {
    m_byte_count = 0;
    m_timeout_active = false;
    m_is_cfg = false;
}

PacketDecoderCore::Completed PacketDecoderCore::on_byte(std::uint8_t byte) {
    if (m_byte_count < static_cast<int>(m_bank.size())) m_bank[static_cast<std::size_t>(m_byte_count)] = byte;
    if (m_crc) return complete_checked(m_byte_count == 0 ? byte == kCfgMarker : m_is_cfg, byte);
    // is_cfg_pkt is updated on byte 0 but the completion tests below read its old value (non-blocking).
    const bool was_cfg = m_is_cfg;
    if (m_byte_count == 0) {
        m_timeout_active = true;
        m_is_cfg = byte == kCfgMarker;
    }
    if (was_cfg && m_byte_count == init_bytes() - 1) {
        latch_init();
        restart();
        return Completed::Init;
    }
    if (!was_cfg && m_byte_count == motion_bytes() - 1) {
        m_motion = motion_fields();
        m_byte_count = 0;
        m_timeout_active = false;  // the RTL leaves is_cfg_pkt as it was (0) here
        return Completed::Motion;
    }
    m_byte_count = (m_byte_count + 1) & (m_ramp ? 0x1F : 0xF);  // byte_count[3:0], a bit more for the ramp's init
    return Completed::None;
}

// With the packet check the type is known from byte 0 on (no seed quirk to keep), and the CRC register runs over
// every byte: after the packet's own CRC it is zero for a packet received as sent.
PacketDecoderCore::Completed PacketDecoderCore::complete_checked(bool is_cfg, std::uint8_t byte) {
    if (m_byte_count == 0) {
        m_timeout_active = true;
        m_is_cfg = is_cfg;
        m_crc_reg = kCrc16Preset;
    }
    m_crc_reg = crc16_update(m_crc_reg, byte);
    const int length = (is_cfg ? init_bytes() : motion_bytes()) + kCrcBytes;
    if (m_byte_count < length - 1) {
        ++m_byte_count;
        return Completed::None;
    }
    const bool good = m_crc_reg == 0;
    restart();
    if (!good) return Completed::BadCrc;
    const auto& b = m_bank;
    if (is_cfg) {
        latch_init();
        return Completed::Init;
    }
    const bool sequence = (b[0] & kSequenceBit) != 0;
    if (m_alternating && m_sequence_seen && sequence == m_last_sequence) return Completed::Repeat;
    m_sequence_seen = true;
    m_last_sequence = sequence;
    m_motion = motion_fields();
    return Completed::Motion;
}

void PacketDecoderCore::on_timeout() {
    restart();
}

}  // namespace cnc::fpga
