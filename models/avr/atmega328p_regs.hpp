// ATmega328P I/O register data-space addresses and bits used by the model (datasheet "Register Summary").
#pragma once
#include <cstdint>

namespace cnc::avr::reg {

inline constexpr std::uint16_t kPinb = 0x23;  // PINB, DDRB, PORTB, PINC, DDRC, PORTC, PIND, DDRD, PORTD
inline constexpr std::uint16_t kPortd = 0x2B;
inline constexpr std::uint16_t kTifr0 = 0x35;
inline constexpr std::uint16_t kTifr1 = 0x36;
inline constexpr std::uint16_t kTifr2 = 0x37;
inline constexpr std::uint16_t kGtccr = 0x43;
inline constexpr std::uint16_t kTccr0a = 0x44;
inline constexpr std::uint16_t kTccr0b = 0x45;
inline constexpr std::uint16_t kTcnt0 = 0x46;
inline constexpr std::uint16_t kOcr0a = 0x47;
inline constexpr std::uint16_t kOcr0b = 0x48;
inline constexpr std::uint16_t kTimsk0 = 0x6E;
inline constexpr std::uint16_t kTimsk1 = 0x6F;
inline constexpr std::uint16_t kTimsk2 = 0x70;
inline constexpr std::uint16_t kTccr1a = 0x80;
inline constexpr std::uint16_t kTccr1b = 0x81;
inline constexpr std::uint16_t kTccr1c = 0x82;
inline constexpr std::uint16_t kTcnt1l = 0x84;
inline constexpr std::uint16_t kTcnt1h = 0x85;
inline constexpr std::uint16_t kIcr1l = 0x86;
inline constexpr std::uint16_t kIcr1h = 0x87;
inline constexpr std::uint16_t kOcr1al = 0x88;
inline constexpr std::uint16_t kOcr1ah = 0x89;
inline constexpr std::uint16_t kOcr1bl = 0x8A;
inline constexpr std::uint16_t kOcr1bh = 0x8B;
inline constexpr std::uint16_t kTccr2a = 0xB0;
inline constexpr std::uint16_t kTccr2b = 0xB1;
inline constexpr std::uint16_t kTcnt2 = 0xB2;
inline constexpr std::uint16_t kOcr2a = 0xB3;
inline constexpr std::uint16_t kOcr2b = 0xB4;
inline constexpr std::uint16_t kAssr = 0xB6;
inline constexpr std::uint16_t kUcsr0a = 0xC0;
inline constexpr std::uint16_t kUcsr0b = 0xC1;
inline constexpr std::uint16_t kUcsr0c = 0xC2;
inline constexpr std::uint16_t kUbrr0l = 0xC4;
inline constexpr std::uint16_t kUbrr0h = 0xC5;
inline constexpr std::uint16_t kUdr0 = 0xC6;

inline constexpr std::uint8_t kTsm = 0x80;      // GTCCR.TSM
inline constexpr std::uint8_t kPsrasy = 0x02;   // GTCCR.PSRASY (Timer2)
inline constexpr std::uint8_t kPsrsync = 0x01;  // GTCCR.PSRSYNC (Timer0/1)
inline constexpr std::uint8_t kAs2 = 0x20;      // ASSR.AS2

}  // namespace cnc::avr::reg
