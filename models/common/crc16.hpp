// CRC-16/CCITT-FALSE (ITU-T V.41 polynomial x^16 + x^12 + x^5 + 1 = 0x1021, register preset to 0xFFFF, bits taken
// most significant first, no final inversion): check value 0x29B1 over the ASCII "123456789" (the CRC catalogue's
// CRC-16/IBM-3740). Bit by bit, as an FPGA computes it one byte per clock, so the model and the RTL share the law.
#pragma once
#include <cstddef>
#include <cstdint>

namespace cnc {

inline constexpr std::uint16_t kCrc16Poly = 0x1021;    // ITU-T V.41
inline constexpr std::uint16_t kCrc16Preset = 0xFFFF;  // CCITT-FALSE preset

// The register after one more byte.
[[nodiscard]] constexpr std::uint16_t crc16_update(std::uint16_t crc, std::uint8_t byte) {
    crc = static_cast<std::uint16_t>(crc ^ (static_cast<std::uint16_t>(byte) << 8U));
    for (int bit = 0; bit < 8; ++bit) {
        crc = (crc & 0x8000U) != 0 ? static_cast<std::uint16_t>((crc << 1U) ^ kCrc16Poly)
                                   : static_cast<std::uint16_t>(crc << 1U);
    }
    return crc;
}

[[nodiscard]] constexpr std::uint16_t crc16(const std::uint8_t* data, std::size_t n) {
    std::uint16_t crc = kCrc16Preset;
    for (std::size_t i = 0; i < n; ++i) crc = crc16_update(crc, data[i]);
    return crc;
}

}  // namespace cnc
