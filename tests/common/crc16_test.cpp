// CRC-16/CCITT-FALSE against the CRC catalogue's check value and the polynomial's defining property.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "common/crc16.hpp"

TEST(Crc16, CatalogueCheckValue) {
    const char* check = "123456789";  // the catalogue's check input
    EXPECT_EQ(cnc::crc16(reinterpret_cast<const std::uint8_t*>(check), std::strlen(check)), 0x29B1);
    EXPECT_EQ(cnc::crc16(nullptr, 0), 0xFFFF);  // the preset alone
}

// A message followed by its CRC, most significant byte first, leaves the register at zero (no final inversion),
// which is how a receiver checks a frame: and any single bit inverted in it leaves a remainder.
TEST(Crc16, AMessageWithItsCrcLeavesZeroAndEverySingleBitErrorIsSeen) {
    std::vector<std::uint8_t> m = {0x01, 0x00, 0x00, 0x01, 0x40, 0xFF, 0xFF, 0xFF, 0x60, 0x04, 0xB0};  // seed 000 §4.9
    const std::uint16_t crc = cnc::crc16(m.data(), m.size());
    m.push_back(static_cast<std::uint8_t>(crc >> 8U));
    m.push_back(static_cast<std::uint8_t>(crc & 0xFFU));
    EXPECT_EQ(cnc::crc16(m.data(), m.size()), 0);
    for (std::size_t byte = 0; byte < m.size(); ++byte) {
        for (int bit = 0; bit < 8; ++bit) {
            m[byte] ^= static_cast<std::uint8_t>(1U << bit);
            EXPECT_NE(cnc::crc16(m.data(), m.size()), 0) << byte << ":" << bit;
            m[byte] ^= static_cast<std::uint8_t>(1U << bit);
        }
    }
}
