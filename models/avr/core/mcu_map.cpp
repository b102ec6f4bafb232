#include "avr/core/mcu_map.hpp"

#include "avr/atmega16_regs.hpp"
#include "avr/atmega328p_regs.hpp"

namespace cnc::avr {

namespace {

constexpr int kOvf = static_cast<int>(TimerFlag::Overflow);
constexpr int kCompA = static_cast<int>(TimerFlag::CompareA);
constexpr int kCompB = static_cast<int>(TimerFlag::CompareB);
constexpr int kCapt = static_cast<int>(TimerFlag::Capture);

McuMap make_328p() {
    McuMap m;
    m.mcu = Mcu::Atmega328p;
    m.name = "atmega328p";
    m.display = "ATmega328P";
    m.flash_bytes = 32 * 1024;  // datasheet §1: 32 KB in-system programmable flash
    m.vector_count = 26;        // Table 11-6 "Reset and Interrupt Vectors in ATmega328P"
    // §1.1: PORTC has 7 pins (PC6 is RESET on an Arduino board, but a port bit all the same).
    m.ports = {{'B', 0x23, 8}, {'C', 0x26, 7}, {'D', 0x29, 8}};
    // OC0A PD6, OC0B PD5, OC1A PB1, OC1B PB2, OC2A PB3, OC2B PD3.
    m.compare_outputs = {{'D', 6, 0, Channel::A}, {'D', 5, 0, Channel::B}, {'B', 1, 1, Channel::A},
                         {'B', 2, 1, Channel::B}, {'B', 3, 2, Channel::A}, {'D', 3, 2, Channel::B}};
    // Timer2 COMPA 7, COMPB 8, OVF 9; Timer1 CAPT 10, COMPA 11, COMPB 12, OVF 13; Timer0 COMPA 14, COMPB 15, OVF 16.
    m.vector[0][kCompA] = 14;
    m.vector[0][kCompB] = 15;
    m.vector[0][kOvf] = 16;
    m.vector[1][kCapt] = 10;
    m.vector[1][kCompA] = 11;
    m.vector[1][kCompB] = 12;
    m.vector[1][kOvf] = 13;
    m.vector[2][kCompA] = 7;
    m.vector[2][kCompB] = 8;
    m.vector[2][kOvf] = 9;
    // ASSR keeps EXCLK (6) and AS2 (5).
    m.timer_regs = {reg::kTcnt0,  reg::kTcnt2, reg::kTcnt1l, reg::kIcr1l, reg::kOcr1al,
                    reg::kOcr1bl, reg::kAssr,  reg::kAs2,    0x60};
    // USART RX 18, UDRE 19, TX 20.
    m.usart = {reg::kUdr0, reg::kUcsr0a, reg::kUcsr0b, reg::kUcsr0c, reg::kUbrr0l, reg::kUbrr0h, 18, 19, 20};
    return m;
}

McuMap make_16() {
    McuMap m;
    m.mcu = Mcu::Atmega16;
    m.name = "atmega16";
    m.display = "ATmega16";
    m.flash_bytes = 16 * 1024;  // ATmega16 datasheet, features: 16 KB in-system programmable flash
    m.vector_count = 21;        // Table 18 "Reset and Interrupt Vectors"
    m.ports = {{'A', 0x39, 8}, {'B', 0x36, 8}, {'C', 0x33, 8}, {'D', 0x30, 8}};
    // OC0 PB3, OC1A PD5, OC1B PD4, OC2 PD7 (one compare unit on Timer0 and Timer2: channel A here).
    m.compare_outputs = {
        {'B', 3, 0, Channel::A}, {'D', 5, 1, Channel::A}, {'D', 4, 1, Channel::B}, {'D', 7, 2, Channel::A}};
    // Table 18: TIMER2 COMP 3, TIMER2 OVF 4, TIMER1 CAPT 5, COMPA 6, COMPB 7, OVF 8, TIMER0 OVF 9, TIMER0 COMP 19.
    m.vector[0][kCompA] = 19;
    m.vector[0][kOvf] = 9;
    m.vector[1][kCapt] = 5;
    m.vector[1][kCompA] = 6;
    m.vector[1][kCompB] = 7;
    m.vector[1][kOvf] = 8;
    m.vector[2][kCompA] = 3;
    m.vector[2][kOvf] = 4;
    m.timer_regs = {reg16::kTcnt0,  reg16::kTcnt2, reg16::kTcnt1l, reg16::kIcr1l, reg16::kOcr1al,
                    reg16::kOcr1bl, reg16::kAssr,  reg16::kAs2,    reg16::kAs2};
    // Table 18: USART RXC 11, UDRE 12, TXC 13.
    m.usart = {reg16::kUdr, reg16::kUcsra, reg16::kUcsrb, reg16::kUcsrcUbrrh, reg16::kUbrrl, reg16::kUcsrcUbrrh, 11, 12,
               13};
    return m;
}

}  // namespace

std::optional<Mcu> mcu_by_name(std::string_view name) {
    if (name == "atmega328p") return Mcu::Atmega328p;
    if (name == "atmega16") return Mcu::Atmega16;
    return std::nullopt;
}

const McuMap& mcu_map(Mcu mcu) {
    static const McuMap m328p = make_328p();
    static const McuMap m16 = make_16();
    return mcu == Mcu::Atmega16 ? m16 : m328p;
}

std::string modelled_mcus() {
    return "atmega328p, atmega16";
}

std::optional<std::pair<int, TimerFlag>> timer_flag_bit(Mcu mcu, int timer, int bit) {
    if (mcu == Mcu::Atmega16) {
        static constexpr std::pair<int, TimerFlag> kBits[8] = {
            {0, TimerFlag::Overflow}, {0, TimerFlag::CompareA}, {1, TimerFlag::Overflow}, {1, TimerFlag::CompareB},
            {1, TimerFlag::CompareA}, {1, TimerFlag::Capture},  {2, TimerFlag::Overflow}, {2, TimerFlag::CompareA}};
        if (bit < 0 || bit > 7) return std::nullopt;
        return kBits[bit];
    }
    switch (bit) {
        case 0:
            return std::make_pair(timer, TimerFlag::Overflow);
        case 1:
            return std::make_pair(timer, TimerFlag::CompareA);
        case 2:
            return std::make_pair(timer, TimerFlag::CompareB);
        case 5:
            if (timer == 1) return std::make_pair(timer, TimerFlag::Capture);
            return std::nullopt;
        default:
            return std::nullopt;
    }
}

}  // namespace cnc::avr
