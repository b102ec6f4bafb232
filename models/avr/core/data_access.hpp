// The data-space bytes an AVR instruction reads and writes, found from its opcode and the registers before it runs
// (AVR Instruction Set Manual: LD/LDD/LDS, ST/STD/STS, PUSH/POP, CALL/RCALL/ICALL, RET/RETI, IN/OUT, SBI/CBI,
// SBIC/SBIS). The fast-forward uses it to learn which bytes an idle loop depends on (models/avr/loop_skipper.hpp).
#pragma once
#include <array>
#include <cstdint>

namespace cnc::avr {

struct DataAccess {
    std::uint16_t addr = 0;
    bool read = false;
    bool write = false;  // after the read when both (SBI, CBI)
};

struct DataAccesses {
    std::array<DataAccess, 2> at{};
    int count = 0;
    // An instruction with effects beyond the data space, or one the ATmega328P lacks: SLEEP, WDR, SPM, BREAK,
    // XCH/LAS/LAC/LAT, EICALL/EIJMP, ELPM, DES, a reserved opcode of the load/store group.
    bool unmodelled = false;
};

// `data` is the data space before the instruction: r0..r31 at 0..31 (X = r27:r26, Y = r29:r28, Z = r31:r30) and SP
// at 0x5D/0x5E. `next_word` is the flash word after the opcode (LDS/STS carry their address there). Instructions
// that touch no data byte (arithmetic, branches, LPM) give none.
[[nodiscard]] DataAccesses data_accesses(std::uint16_t opcode, std::uint16_t next_word, const std::uint8_t* data);

}  // namespace cnc::avr
