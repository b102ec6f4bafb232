// What a flash image's reset and interrupt vector table says of its MCU, for a firmware that names none (an Intel
// HEX file, or an ELF without a .mmcu section or avr-libc's device note). avr-gcc's start-up code puts one entry per
// vector at address 0, 4 bytes each on both modelled MCUs: a JMP, or an RJMP and a NOP where avr-ld --relax
// shortened it. The ATmega328P has 26 vectors, the ATmega16 21 (McuMap::vector_count).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "avr/core/mcu_map.hpp"

namespace cnc::avr {

// The number of consecutive vector-table entries from address 0 (at most `limit`).
[[nodiscard]] int vector_table_entries(const std::vector<std::uint8_t>& flash, int limit);

// Throws BadInput(where, ...) when the image's table has exactly another modelled MCU's number of entries and not
// `mcu`'s: built for that MCU. A table that matches no modelled MCU (a firmware without avr-gcc's start-up code)
// proves nothing and passes. `mcu_key` as check_avr_elf's.
void check_vector_table(const std::vector<std::uint8_t>& flash, Mcu mcu, const std::string& path,
                        const std::string& where, const std::string& mcu_key);

}  // namespace cnc::avr
