// The two MCUs the AVR model runs, as far as the model's own units need them: where their ports are, which pins
// the timers' compare outputs drive, which interrupt vector each timer flag raises, and how the timer interrupt
// mask/flag registers are laid out. Datasheets: ATmega328P "Register Summary" and "Interrupt Vectors in
// ATmega328P"; ATmega16 (doc2466) "Register Summary", Table 18 "Reset and Interrupt Vectors", "Alternate
// Functions of Port B/D".
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "avr/core/timer_unit.hpp"

namespace cnc::avr {

enum class Mcu { Atmega328p, Atmega16 };

struct PortAddr {
    char port = 'B';
    std::uint16_t pin = 0;  // PINx data-space address; DDRx = pin + 1, PORTx = pin + 2 on both MCUs
};

struct CompareOutputPin {
    char port = 'B';
    int bit = 0;
    int timer = 0;
    Channel channel = Channel::A;
};

// The timer registers both MCUs have with the same function at their own data-space addresses: the counters,
// Timer1's 16-bit registers (accessed through TEMP) and ASSR.
struct TimerRegs {
    std::uint16_t tcnt0 = 0;
    std::uint16_t tcnt2 = 0;
    std::uint16_t tcnt1l = 0;  // each xH register is the next address
    std::uint16_t icr1l = 0;
    std::uint16_t ocr1al = 0;
    std::uint16_t ocr1bl = 0;
    std::uint16_t assr = 0;
    std::uint8_t assr_as2 = 0;       // ASSR.AS2: Timer2 clocked asynchronously (not modelled)
    std::uint8_t assr_writable = 0;  // the bits a write keeps
};

struct McuMap {
    Mcu mcu = Mcu::Atmega328p;
    const char* name = "";  // as avr-gcc's -mmcu and simavr's core name
    std::size_t flash_bytes = 0;
    std::vector<PortAddr> ports;
    std::vector<CompareOutputPin> compare_outputs;
    // Vector number of each timer flag (0: the timer has no such flag).
    int vector[3][4] = {};  // [timer][TimerFlag]
    TimerRegs timer_regs;
};

// "atmega328p" or "atmega16"; nullopt for any other.
[[nodiscard]] std::optional<Mcu> mcu_by_name(std::string_view name);
[[nodiscard]] const McuMap& mcu_map(Mcu mcu);
// "atmega328p, atmega16", for messages.
[[nodiscard]] std::string modelled_mcus();

// The timer flag a bit of a timer interrupt mask or flag register stands for: on the ATmega328P TIMSKn/TIFRn
// (n = `timer`), bits TOVn 0, OCFnA 1, OCFnB 2, ICF1 5; on the ATmega16 the single TIMSK/TIFR (`timer`
// ignored): TOV0 0, OCF0 1, TOV1 2, OCF1B 3, OCF1A 4, ICF1 5, TOV2 6, OCF2 7.
[[nodiscard]] std::optional<std::pair<int, TimerFlag>> timer_flag_bit(Mcu mcu, int timer, int bit);

}  // namespace cnc::avr
