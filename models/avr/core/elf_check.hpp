// Checks a firmware file before libsimavr sees it: simavr's ELF loader trusts its input and may abort on a file
// that is not an AVR ELF, and it would happily run a firmware built for another MCU or clock.
#pragma once
#include <cstdint>
#include <string>

namespace cnc::avr {

struct ElfInfo {
    // The MCU it was built for: the simavr .mmcu section's (AVR_MCU(F_CPU, "atmega328p")), else the device name of
    // avr-libc's .note.gnu.avr.deviceinfo note (every avr-gcc -mmcu build with avr-libc 2.0 or later), else empty.
    std::string mmcu;
    std::string mmcu_source;         // the section it came from, for messages
    std::uint32_t frequency_hz = 0;  // from the .mmcu section, 0 when absent
    int avr_arch = 0;                // e_flags & EF_AVR_MACH: 5 for avr5 (ATmega328P), 6 for avr6 (ATmega2560), ...
};

// Throws BadInput(where, ...) naming `path` and what was found when the file is missing or unreadable, not an
// ELF, an ELF for another machine (e_machine != EM_AVR), built for another MCU than `mcu` (ElfInfo::mmcu, or its
// AVR architecture when it names none), or declares another F_CPU than `f_cpu_hz`. `mcu_key`: the scenario key
// that chose `mcu`, named in the message (empty: "the model").
[[nodiscard]] ElfInfo check_avr_elf(const std::string& path, const std::string& mcu, std::uint32_t f_cpu_hz,
                                    const std::string& where, const std::string& mcu_key = "");

// "the model is an atmega328p", or with a key "avr.mcu is atmega328p": the end of a wrong-MCU message.
[[nodiscard]] std::string mcu_named(const std::string& mcu, const std::string& mcu_key);

}  // namespace cnc::avr
