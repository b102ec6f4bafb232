// The vector-table check of a firmware that names no MCU: avr-gcc's start-up code lays out one 4-byte entry per
// vector, 26 on the ATmega328P (its datasheet's Table 11-6), 21 on the ATmega16 (doc2466 Table 18).
#include <gtest/gtest.h>

#include <vector>

#include "avr/core/vector_table.hpp"
#include "common/bad_input.hpp"

using namespace cnc::avr;

namespace {

// `entries` vector entries (JMP 0x0068: 0x940C 0x0034, or with `relaxed` RJMP .+N and NOP), then `eor r1, r1`.
std::vector<std::uint8_t> image(int entries, bool relaxed) {
    std::vector<std::uint8_t> out;
    for (int i = 0; i < entries; ++i) {
        if (relaxed)
            out.insert(out.end(), {0x2F, 0xC0, 0x00, 0x00});
        else
            out.insert(out.end(), {0x0C, 0x94, 0x34, 0x00});
    }
    out.insert(out.end(), {0x11, 0x24, 0x1F, 0xBE});
    return out;
}

std::string error_of(const std::vector<std::uint8_t>& flash, Mcu mcu) {
    try {
        check_vector_table(flash, mcu, "fw.hex", "s.toml: avr.firmware", "avr.mcu");
    } catch (const cnc::BadInput& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(AvrVectorTable, CountsJmpAndRelaxedRjmpEntries) {
    EXPECT_EQ(vector_table_entries(image(26, false), 100), 26);
    EXPECT_EQ(vector_table_entries(image(21, true), 100), 21);
    EXPECT_EQ(vector_table_entries(image(26, false), 22), 22);
    EXPECT_EQ(vector_table_entries({0x11, 0x24}, 100), 0);
}

TEST(AvrVectorTable, RefusesAnotherModelledMcusTable) {
    EXPECT_EQ(error_of(image(26, false), Mcu::Atmega328p), "");
    EXPECT_EQ(error_of(image(21, true), Mcu::Atmega16), "");
    EXPECT_EQ(error_of(image(21, false), Mcu::Atmega328p),
              "s.toml: avr.firmware: firmware 'fw.hex' starts with a vector table of 21 entries, the ATmega16's (the "
              "ATmega328P has 26): it was built for the atmega16, avr.mcu is atmega328p");
    EXPECT_NE(error_of(image(26, true), Mcu::Atmega16).find("26 entries, the ATmega328P's (the ATmega16 has 21)"),
              std::string::npos);
    // A table of neither size (no avr-gcc start-up code) proves nothing.
    EXPECT_EQ(error_of(image(1, false), Mcu::Atmega16), "");
    EXPECT_EQ(error_of(image(30, false), Mcu::Atmega328p), "");
}
