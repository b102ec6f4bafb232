// data_accesses() on opcodes assembled by GNU as (avr-as -mmcu=atmega328p, disassembled with avr-objdump): the
// addresses the AVR Instruction Set Manual gives each instruction with X = 0x0123, Y = 0x0200, Z = 0x0300 and
// SP = 0x08F0.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

#include "avr/core/data_access.hpp"

using namespace cnc::avr;

namespace {

struct Expect {
    std::uint16_t opcode;
    std::uint16_t next_word;
    const char* text;
    std::vector<DataAccess> accesses;
};

bool operator==(const DataAccess& a, const DataAccess& b) {
    return a.addr == b.addr && a.read == b.read && a.write == b.write;
}

DataAccess rd(std::uint16_t a) {
    return {a, true, false};
}
DataAccess wr(std::uint16_t a) {
    return {a, false, true};
}

std::array<std::uint8_t, 0x900> registers() {
    std::array<std::uint8_t, 0x900> d{};
    d[26] = 0x23;  // X
    d[27] = 0x01;
    d[28] = 0x00;  // Y
    d[29] = 0x02;
    d[30] = 0x00;  // Z
    d[31] = 0x03;
    d[0x5D] = 0xF0;  // SP
    d[0x5E] = 0x08;
    return d;
}

}  // namespace

TEST(AvrDataAccess, LoadsStoresStackAndIoOfEachAddressingMode) {
    const std::vector<Expect> cases = {
        {0x9180, 0x0123, "lds r24, 0x0123", {rd(0x0123)}},
        {0x9390, 0x0456, "sts 0x0456, r25", {wr(0x0456)}},
        {0x903c, 0, "ld r3, X", {rd(0x0123)}},
        {0x903d, 0, "ld r3, X+", {rd(0x0123)}},
        {0x903e, 0, "ld r3, -X", {rd(0x0122)}},
        {0x9049, 0, "ld r4, Y+", {rd(0x0200)}},
        {0x904a, 0, "ld r4, -Y", {rd(0x01FF)}},
        {0x8058, 0, "ld r5, Y", {rd(0x0200)}},
        {0xac5f, 0, "ldd r5, Y+63", {rd(0x023F)}},
        {0x9061, 0, "ld r6, Z+", {rd(0x0300)}},
        {0x9062, 0, "ld r6, -Z", {rd(0x02FF)}},
        {0x8070, 0, "ld r7, Z", {rd(0x0300)}},
        {0x8871, 0, "ldd r7, Z+17", {rd(0x0311)}},
        {0x928c, 0, "st X, r8", {wr(0x0123)}},
        {0x928d, 0, "st X+, r8", {wr(0x0123)}},
        {0x928e, 0, "st -X, r8", {wr(0x0122)}},
        {0x9299, 0, "st Y+, r9", {wr(0x0200)}},
        {0x929a, 0, "st -Y, r9", {wr(0x01FF)}},
        {0x82a8, 0, "st Y, r10", {wr(0x0200)}},
        {0xa6aa, 0, "std Y+42, r10", {wr(0x022A)}},
        {0x92b1, 0, "st Z+, r11", {wr(0x0300)}},
        {0x92b2, 0, "st -Z, r11", {wr(0x02FF)}},
        {0x82c0, 0, "st Z, r12", {wr(0x0300)}},
        {0x82c5, 0, "std Z+5, r12", {wr(0x0305)}},
        {0x92df, 0, "push r13", {wr(0x08F0)}},
        {0x90ef, 0, "pop r14", {rd(0x08F1)}},
        {0x940e, 0x0080, "call 0x100", {wr(0x08F0), wr(0x08EF)}},
        {0xd000, 0, "rcall .+0", {wr(0x08F0), wr(0x08EF)}},
        {0x9509, 0, "icall", {wr(0x08F0), wr(0x08EF)}},
        {0x9508, 0, "ret", {rd(0x08F1), rd(0x08F2)}},
        {0x9518, 0, "reti", {rd(0x08F1), rd(0x08F2)}},
        {0xb70f, 0, "in r16, 0x3f", {rd(0x5F)}},
        {0xb105, 0, "in r16, 0x05", {rd(0x25)}},
        {0xbf1e, 0, "out 0x3e, r17", {wr(0x5E)}},
        {0xb91b, 0, "out 0x0b, r17", {wr(0x2B)}},
        {0x9a29, 0, "sbi 0x05, 1", {{0x25, true, true}}},
        {0x98ff, 0, "cbi 0x1f, 7", {{0x3F, true, true}}},
        {0x994a, 0, "sbic 0x09, 2", {rd(0x29)}},
        {0x9bf0, 0, "sbis 0x1e, 0", {rd(0x3E)}},
        {0x9004, 0, "lpm r0, Z", {}},
        {0x9015, 0, "lpm r1, Z+", {}},
        {0x0c12, 0, "add r1, r2", {}},
        {0xc000, 0, "rjmp .+0", {}},
    };
    const auto data = registers();
    for (const Expect& e : cases) {
        const DataAccesses got = data_accesses(e.opcode, e.next_word, data.data());
        EXPECT_FALSE(got.unmodelled) << e.text;
        ASSERT_EQ(got.count, static_cast<int>(e.accesses.size())) << e.text;
        for (int i = 0; i < got.count; ++i)
            EXPECT_TRUE(got.at[static_cast<std::size_t>(i)] == e.accesses[static_cast<std::size_t>(i)])
                << e.text << " access " << i;
    }
}

TEST(AvrDataAccess, InstructionsWithEffectsBeyondTheDataSpaceAreFlagged) {
    const auto data = registers();
    for (const std::uint16_t op : {0x9588, 0x95a8, 0x95e8, 0x9598})  // sleep, wdr, spm, break
        EXPECT_TRUE(data_accesses(op, 0, data.data()).unmodelled) << std::hex << op;
}
