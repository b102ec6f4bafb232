// The two MCUs the AVR model runs, as far as the model's own units need them: where their ports are, which pins
// the timers' compare outputs drive, which interrupt vector each timer flag raises, and how the timer interrupt
// mask/flag registers are laid out. Datasheets: ATmega328P "Register Summary" and "Interrupt Vectors in
// ATmega328P"; ATmega16 (doc2466) "Register Summary", Table 18 "Reset and Interrupt Vectors", "Alternate
// Functions of Port B/D".
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "avr/core/timer_unit.hpp"

namespace cnc::avr {

enum class Mcu { Atmega328p, Atmega16 };
inline constexpr std::array<Mcu, 2> kModelledMcus{Mcu::Atmega328p, Mcu::Atmega16};

struct PortAddr {
    char port = 'B';
    std::uint16_t pin = 0;  // PINx data-space address; DDRx = pin + 1, PORTx = pin + 2 on both MCUs
    int bits = 8;           // its pins are Px0 .. Px(bits - 1)
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

// USART0 (ATmega328P) / the USART (ATmega16): its registers' data-space addresses and its vectors. The ATmega16's
// UCSRC and UBRRH share one address (datasheet doc2466 "Accessing UBRRH/UCSRC Registers": URSEL selects).
struct UsartRegs {
    std::uint16_t udr = 0;
    std::uint16_t ucsra = 0;
    std::uint16_t ucsrb = 0;
    std::uint16_t ucsrc = 0;
    std::uint16_t ubrrl = 0;
    std::uint16_t ubrrh = 0;
    int vector_rxc = 0;
    int vector_udre = 0;
    int vector_txc = 0;
    [[nodiscard]] bool shared_ucsrc() const { return ucsrc == ubrrh; }
};

struct McuMap {
    Mcu mcu = Mcu::Atmega328p;
    const char* name = "";     // as avr-gcc's -mmcu and simavr's core name
    const char* display = "";  // as its datasheet writes it
    std::size_t flash_bytes = 0;
    int vector_count = 0;  // the reset and interrupt vectors, each a JMP (2 words) on both MCUs
    int avr_arch = 5;      // avr-gcc's architecture (ELF e_flags): avr5 for both
    std::vector<PortAddr> ports;
    std::vector<CompareOutputPin> compare_outputs;
    // Vector number of each timer flag (0: the timer has no such flag).
    int vector[3][4] = {};  // [timer][TimerFlag]
    TimerRegs timer_regs;
    UsartRegs usart;
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
