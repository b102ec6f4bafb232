#include "fpga/core/packet_decoder_core.hpp"

namespace cnc::fpga {

namespace {
std::uint32_t be32(std::uint8_t a, std::uint8_t b, std::uint8_t c, std::uint8_t d) {
    return (std::uint32_t{a} << 24) | (std::uint32_t{b} << 16) | (std::uint32_t{c} << 8) | std::uint32_t{d};
}
}  // namespace

PacketDecoderCore::Completed PacketDecoderCore::on_byte(std::uint8_t byte) {
    if (m_byte_count < static_cast<int>(m_bank.size())) m_bank[static_cast<std::size_t>(m_byte_count)] = byte;
    // is_cfg_pkt is updated on byte 0 but the completion tests below read its old value (non-blocking).
    const bool was_cfg = m_is_cfg;
    if (m_byte_count == 0) {
        m_timeout_active = true;
        m_is_cfg = byte == kCfgMarker;
    }
    const auto& b = m_bank;
    if (was_cfg && m_byte_count == kInitBytes - 1) {
        m_init.num_x = be32(b[1], b[2], b[3], b[4]);
        m_init.num_y = be32(b[5], b[6], b[7], byte);
        m_byte_count = 0;
        m_timeout_active = false;
        m_is_cfg = false;
        return Completed::Init;
    }
    if (!was_cfg && m_byte_count == kMotionBytes - 1) {
        m_motion.motion = static_cast<std::uint8_t>(b[0] & 0x3U);
        m_motion.steps_x = static_cast<std::int32_t>(be32(b[1], b[2], b[3], b[4]));
        m_motion.steps_y = static_cast<std::int32_t>(be32(b[5], b[6], b[7], b[8]));
        m_motion.feed = static_cast<std::uint16_t>((b[9] << 8) | byte);
        m_byte_count = 0;
        m_timeout_active = false;  // the RTL leaves is_cfg_pkt as it was (0) here
        return Completed::Motion;
    }
    m_byte_count = (m_byte_count + 1) & 0xF;  // byte_count[3:0]
    return Completed::None;
}

void PacketDecoderCore::on_timeout() {
    m_byte_count = 0;
    m_timeout_active = false;
    m_is_cfg = false;
}

}  // namespace cnc::fpga
