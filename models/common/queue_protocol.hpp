// The packet queue's protocol (fpga.queue_depth, our option on seed 000 §7.2's proposal of a command queue and a
// FIFO packet buffer so that the host sends ahead), shared by the host's sender and the FPGA's queue so that both
// ends read the same frame.
//
// Motion packets keep the seed's 11 bytes (and the packet check's CRC after them); bits 6:2 of the motion byte
// number them modulo 32 (bits 1:0 stay the motion, bit 7 stays 0, so that no motion byte is the init marker 0xFF).
// The FPGA answers every packet it completes, and every move its queue hands step_gen or sees end, with a 2-byte
// status:
//   byte 0: 1 1 running free[4:0]   running: step_gen has a move; free: queue slots free (0 .. depth)
//   byte 1: 1 0 refused next[4:0]   refused: the packet just completed was not queued (bad CRC, out of order or no
//                                   slot); next: the number of the next packet the queue takes
// The host keeps packets next .. next+free-1 in flight and, after a refusal or no status, sends again from next
// (go-back-N): a packet numbered below next was queued already (its status was lost) and is answered, not queued
// again; one numbered above next is refused.
#pragma once
#include <array>
#include <cstdint>
#include <optional>

namespace cnc::queue_protocol {

inline constexpr int kSeqModulo = 32;  // bits 6:2 of the motion byte
inline constexpr int kMaxDepth = 16;   // a window of at most half the numbers: behind and ahead stay apart
inline constexpr int kSeqShift = 2;
inline constexpr std::uint8_t kSeqMask = 0x1F;
inline constexpr std::uint8_t kStatusByte0 = 0xC0;  // bits 7:6 of each status byte say which one it is
inline constexpr std::uint8_t kStatusByte1 = 0x80;
inline constexpr std::uint8_t kTagMask = 0xC0;
inline constexpr std::uint8_t kFlagBit = 0x20;  // running in byte 0, refused in byte 1
inline constexpr std::uint8_t kValueMask = 0x1F;

struct Status {
    int next_seq = 0;
    int free = 0;
    bool running = false;
    bool refused = false;
};
[[nodiscard]] inline bool operator==(const Status& a, const Status& b) {
    return a.next_seq == b.next_seq && a.free == b.free && a.running == b.running && a.refused == b.refused;
}

[[nodiscard]] inline std::uint8_t with_seq(std::uint8_t motion_byte, int seq) {
    return static_cast<std::uint8_t>((motion_byte & 0x3U) | ((static_cast<unsigned>(seq) & kSeqMask) << kSeqShift));
}
[[nodiscard]] inline int seq_of(std::uint8_t motion_byte) { return (motion_byte >> kSeqShift) & kSeqMask; }
// How far `seq` is past `from`, modulo 32 (0 .. 31).
[[nodiscard]] inline int seq_distance(int from, int seq) { return ((seq - from) % kSeqModulo + kSeqModulo) % kSeqModulo; }

[[nodiscard]] inline std::array<std::uint8_t, 2> encode(const Status& s) {
    return {static_cast<std::uint8_t>(kStatusByte0 | (s.running ? kFlagBit : 0) | (s.free & kValueMask)),
            static_cast<std::uint8_t>(kStatusByte1 | (s.refused ? kFlagBit : 0) | (s.next_seq & kValueMask))};
}

// Reads the FPGA's bytes one at a time: a byte 0 then a byte 1 is a status; anything else is stray (a byte lost or
// hit on the wire) and starts over.
class StatusReader {
public:
    // The status `byte` completes, if any; `stray` set when the byte fits no status.
    std::optional<Status> feed(std::uint8_t byte, bool& stray) {
        stray = false;
        if ((byte & kTagMask) == kStatusByte0) {
            stray = m_have_first;
            m_have_first = true;
            m_first = byte;
            return std::nullopt;
        }
        if ((byte & kTagMask) != kStatusByte1 || !m_have_first) {
            stray = true;
            m_have_first = false;
            return std::nullopt;
        }
        Status s;
        s.running = (m_first & kFlagBit) != 0;
        s.free = m_first & kValueMask;
        s.refused = (byte & kFlagBit) != 0;
        s.next_seq = byte & kValueMask;
        m_have_first = false;
        return s;
    }

private:
    bool m_have_first = false;
    std::uint8_t m_first = 0;
};

}  // namespace cnc::queue_protocol
