#include "avr/core/vector_table.hpp"

#include <algorithm>

#include "avr/core/elf_check.hpp"
#include "common/bad_input.hpp"

namespace cnc::avr {

namespace {

// AVR instruction set manual: JMP = 1001 010k kkkk 110k (two words), RJMP = 1100 kkkk kkkk kkkk, NOP = 0.
bool is_jmp(std::uint16_t op) {
    return (op & 0xFE0EU) == 0x940CU;
}
bool is_rjmp(std::uint16_t op) {
    return (op & 0xF000U) == 0xC000U;
}

}  // namespace

int vector_table_entries(const std::vector<std::uint8_t>& flash, int limit) {
    const auto word = [&](std::size_t at) { return static_cast<std::uint16_t>(flash[at] | (flash[at + 1] << 8)); };
    int n = 0;
    for (std::size_t at = 0; n < limit && at + 4 <= flash.size(); at += 4, ++n) {
        const std::uint16_t first = word(at);
        if (!is_jmp(first) && !(is_rjmp(first) && word(at + 2) == 0)) break;
    }
    return n;
}

void check_vector_table(const std::vector<std::uint8_t>& flash, Mcu mcu, const std::string& path,
                        const std::string& where, const std::string& mcu_key) {
    const McuMap& own = mcu_map(mcu);
    int limit = own.vector_count;
    for (const Mcu other : kModelledMcus) limit = std::max(limit, mcu_map(other).vector_count);
    const int entries = vector_table_entries(flash, limit + 1);
    if (entries == own.vector_count) return;
    for (const Mcu other : kModelledMcus) {
        const McuMap& m = mcu_map(other);
        if (other == mcu || entries != m.vector_count) continue;
        throw BadInput(where, "firmware '" + path + "' starts with a vector table of " + std::to_string(entries) +
                                  " entries, the " + m.display + "'s (the " + own.display + " has " +
                                  std::to_string(own.vector_count) + "): it was built for the " + m.name + ", " +
                                  mcu_named(own.name, mcu_key));
    }
}

}  // namespace cnc::avr
