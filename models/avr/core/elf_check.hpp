// Checks a firmware file before libsimavr sees it: simavr's ELF loader trusts its input and may abort on a file
// that is not an AVR ELF, and it would happily run a firmware built for another MCU or clock.
#pragma once
#include <cstdint>
#include <string>

namespace cnc::avr {

struct ElfInfo {
    std::string mmcu;                // from the simavr .mmcu section (AVR_MCU(F_CPU, "atmega328p")), or empty
    std::uint32_t frequency_hz = 0;  // from the .mmcu section, 0 when absent
    int avr_arch = 0;                // e_flags & EF_AVR_MACH: 5 for avr5 (ATmega328P), 6 for avr6 (ATmega2560), ...
};

// Throws BadInput(where, ...) naming `path` and what was found when the file is missing or unreadable, not an
// ELF, an ELF for another machine (e_machine != EM_AVR), built for another MCU than `mcu` (its .mmcu section, or
// its AVR architecture when there is no .mmcu section), or declares another F_CPU than `f_cpu_hz`.
[[nodiscard]] ElfInfo check_avr_elf(const std::string& path, const std::string& mcu, std::uint32_t f_cpu_hz,
                                    const std::string& where);

}  // namespace cnc::avr
