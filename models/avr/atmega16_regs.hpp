// ATmega16 I/O register data-space addresses and bits used by the model (datasheet doc2466 "Register Summary":
// I/O address + 0x20).
#pragma once
#include <cstdint>

namespace cnc::avr::reg16 {

inline constexpr std::uint16_t kOcr0 = 0x5C;
inline constexpr std::uint16_t kGicr = 0x5B;
inline constexpr std::uint16_t kGifr = 0x5A;
inline constexpr std::uint16_t kTimsk = 0x59;
inline constexpr std::uint16_t kTifr = 0x58;
inline constexpr std::uint16_t kMcucr = 0x55;
inline constexpr std::uint16_t kTccr0 = 0x53;
inline constexpr std::uint16_t kTcnt0 = 0x52;
inline constexpr std::uint16_t kSfior = 0x50;
inline constexpr std::uint16_t kTccr1a = 0x4F;
inline constexpr std::uint16_t kTccr1b = 0x4E;
inline constexpr std::uint16_t kTcnt1h = 0x4D;
inline constexpr std::uint16_t kTcnt1l = 0x4C;
inline constexpr std::uint16_t kOcr1ah = 0x4B;
inline constexpr std::uint16_t kOcr1al = 0x4A;
inline constexpr std::uint16_t kOcr1bh = 0x49;
inline constexpr std::uint16_t kOcr1bl = 0x48;
inline constexpr std::uint16_t kIcr1h = 0x47;
inline constexpr std::uint16_t kIcr1l = 0x46;
inline constexpr std::uint16_t kTccr2 = 0x45;
inline constexpr std::uint16_t kTcnt2 = 0x44;
inline constexpr std::uint16_t kOcr2 = 0x43;
inline constexpr std::uint16_t kAssr = 0x42;
inline constexpr std::uint16_t kUcsrcUbrrh = 0x40;  // UCSRC when written with URSEL = 1, else UBRRH
inline constexpr std::uint16_t kUdr = 0x2C;
inline constexpr std::uint16_t kUcsra = 0x2B;
inline constexpr std::uint16_t kUcsrb = 0x2A;
inline constexpr std::uint16_t kUbrrl = 0x29;

inline constexpr int kVecInt0 = 1;  // Table 18: INT0 1, INT1 2
inline constexpr int kVecInt1 = 2;
inline constexpr std::uint8_t kIntf0 = 0x40;  // GICR.INT0 / GIFR.INTF0 (bit 6); INT1 / INTF1 bit 7
inline constexpr std::uint8_t kIntf1 = 0x80;
inline constexpr std::uint8_t kPsr2 = 0x02;   // SFIOR.PSR2: Timer2 prescaler reset
inline constexpr std::uint8_t kPsr10 = 0x01;  // SFIOR.PSR10: Timer0/1 prescaler reset
inline constexpr std::uint8_t kAs2 = 0x08;    // ASSR.AS2
inline constexpr std::uint8_t kUrsel = 0x80;  // UCSRC.URSEL: reads 1 in UCSRC, 0 in UBRRH

}  // namespace cnc::avr::reg16
