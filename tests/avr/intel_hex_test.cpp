// Intel HEX records against the format's specification: the checksum makes a record's bytes sum to 0 mod 256, the
// extended addresses move the data, gaps read as erased flash, and a bad file is named with its line.
#include <gtest/gtest.h>

#include <string>

#include "avr/core/intel_hex.hpp"
#include "common/bad_input.hpp"

namespace cnc::avr {
namespace {

std::string error_of(const std::string& text, std::size_t flash = 1024) {
    try {
        (void)parse_intel_hex(text, "fw.hex", flash, "s.toml: avr.firmware");
    } catch (const BadInput& e) {
        return e.what();
    }
    return "";
}

// The checksum of ":0400000001020304F2" is 0x100 - (4 + 1 + 2 + 3 + 4) = 0xF2; of ":02000600AABB93",
// 0x100 - (2 + 6 + 0xAA + 0xBB) mod 256 = 0x93.
TEST(IntelHex, DataRecordsAtTheirAddresses) {
    const std::vector<std::uint8_t> image =
        parse_intel_hex(":0400000001020304F2\r\n:02000600AABB93\n:00000001FF\n", "fw.hex", 1024, "w");
    const std::vector<std::uint8_t> expected{1, 2, 3, 4, 0xFF, 0xFF, 0xAA, 0xBB};
    EXPECT_EQ(image, expected);
}

// An extended linear address 0x0000 and an extended segment address 0x0010 (x 16 = 0x100) move the next record.
TEST(IntelHex, ExtendedAddresses) {
    const std::vector<std::uint8_t> image =
        parse_intel_hex(":020000040000FA\n:020000020010EC\n:0100000055AA\n:00000001FF\n", "fw.hex", 1024, "w");
    ASSERT_EQ(image.size(), 0x101U);
    EXPECT_EQ(image[0x100], 0x55);
    EXPECT_EQ(image[0], 0xFF);
}

TEST(IntelHex, BadFilesAreNamedWithTheirLine) {
    EXPECT_NE(error_of(":0400000001020304F3\n:00000001FF\n").find("fw.hex:1: checksum wrong"), std::string::npos);
    EXPECT_NE(error_of("\n:04000000010203F5\n").find("fw.hex:2: the record says 4 data bytes, it has 3"),
              std::string::npos);
    EXPECT_NE(error_of("G0 X1\n").find("fw.hex:1: not an Intel HEX record"), std::string::npos);
    EXPECT_NE(error_of(":0400000001020304F2\n").find("no end-of-file record"), std::string::npos);
    EXPECT_NE(error_of(":0400000001020304F2\n:00000001FF\n", 3).find("beyond the MCU's 3-byte flash"),
              std::string::npos);
    EXPECT_NE(error_of(":0400000001020304F3\n").find("s.toml: avr.firmware"), std::string::npos);
}

}  // namespace
}  // namespace cnc::avr
