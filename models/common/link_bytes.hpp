// The single bytes seed 000's FPGA sends its host, shared by the FPGA models and the host's sender so that both
// ends read one definition.
#pragma once
#include <cstdint>

namespace cnc {

inline constexpr std::uint8_t kAckByte = 0xAA;  // seed 000 §4.11: a move completed
// With the packet check (protocol.crc = "crc16", our option on seed 000 §7.2): a packet whose CRC failed; the ACK's
// bits inverted, so that no single bit error turns one into the other.
inline constexpr std::uint8_t kNakByte = 0x55;
// With the e-stop input (fpga.estop, our option on seed 000 §7.2): the FPGA halted. Four bits from the ACK and from
// the NAK, and tagged 01 like the NAK, so that the packet queue's statuses (tags 11 and 10) never read as it.
inline constexpr std::uint8_t kHaltByte = 0x4B;

}  // namespace cnc
