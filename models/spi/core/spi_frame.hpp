// The spi-fpga frame layout (the seed 004 thesis leaves it open; models/spi/README.md has the byte table). One
// full-duplex transfer carries a command frame on MOSI and a feedback frame on MISO, both 1 + 4 x n_axes
// bytes, big-endian, MSB first on the wire:
//   MOSI: [command 0x52] then per axis a 32-bit rate word: bit 31 = direction (1 = forward, DIR pin high),
//         bit 30 = laser on in the first (X) word, reserved (sent 0, ignored) in the others, bits 29..0 = the
//         pulse generator's period in FPGA clocks, 0 = stopped (the direction is then ignored).
//   MISO: [status] then per axis the signed 32-bit step counter (wraps mod 2^32; the host widens it).
// A period word rather than a DDS increment (hm2) or a frequency (Remora): the seed's pulse generator counts a
// period in clocks (§5.1.3), so the host does the division and the FPGA needs none. The laser rides in a bit of the
// X word, not in a byte of its own, so that the frame stays 9 bytes with the 0x52 header (sigrok decodes that).
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace cnc::spi {

inline constexpr std::uint8_t kCmdRates = 0x52;  // 'R': "apply these rates"; anything else is rejected
inline constexpr std::size_t kHeaderBytes = 1;
inline constexpr std::size_t kBytesPerAxis = 4;
inline constexpr std::uint32_t kDirForwardBit = 0x8000'0000U;
inline constexpr std::uint32_t kLaserOnBit = 0x4000'0000U;      // in the X word only; reserved in the others
inline constexpr std::uint32_t kPeriodMask = 0x3FFF'FFFFU;      // bits 29..0
inline constexpr std::uint32_t kMaxPeriodCycles = kPeriodMask;  // 2^30 - 1: 21.5 s between steps at 50 MHz

// Status byte (first MISO byte), taken when SS falls (see models/fpga/spi/README.md for the edge).
inline constexpr std::uint8_t kStatusAlive = 0x80;      // always 1: a MISO stuck low (no FPGA) reads 0x00
inline constexpr std::uint8_t kStatusRejected = 0x40;   // a frame was rejected (length, header) since the last reply
inline constexpr std::uint8_t kStatusDropped = 0x20;    // a frame was dropped (FIFO full) since the last reply
inline constexpr std::uint8_t kStatusFull = 0x10;       // FIFO full
inline constexpr std::uint8_t kStatusLevelMask = 0x0F;  // FIFO level (frames held), saturates at 15

struct AxisRate {
    std::uint32_t period_cycles = 0;  // 0 = stopped
    bool forward = true;              // DIR pin level while stepping
    friend bool operator==(const AxisRate& a, const AxisRate& b) {
        return a.period_cycles == b.period_cycles && a.forward == b.forward;
    }
};

// One command frame: a rate word per axis and the laser bit (carried in the X word).
struct Command {
    std::vector<AxisRate> axes;
    bool laser_on = false;
    friend bool operator==(const Command& a, const Command& b) { return a.axes == b.axes && a.laser_on == b.laser_on; }
};

struct SlaveStatus {
    std::uint32_t fifo_level = 0;  // frames in the FIFO (the byte saturates at 15)
    bool fifo_full = false;
    bool dropped = false;
    bool rejected = false;
    friend bool operator==(const SlaveStatus& a, const SlaveStatus& b) {
        return a.fifo_level == b.fifo_level && a.fifo_full == b.fifo_full && a.dropped == b.dropped &&
               a.rejected == b.rejected;
    }
};

struct Feedback {
    SlaveStatus status;
    std::vector<std::int32_t> counts;  // per axis, as sent (mod 2^32)
};

[[nodiscard]] constexpr std::size_t frame_bytes(std::size_t n_axes) {
    return kHeaderBytes + kBytesPerAxis * n_axes;
}
[[nodiscard]] constexpr std::size_t frame_bits(std::size_t n_axes) {
    return 8 * frame_bytes(n_axes);
}

// Rate word of one axis, bit 30 clear. BadInput (naming `where` and the numbers) for a period above the 30-bit
// field or a non-zero period below min_period_cycles (the FPGA's shortest STEP period).
[[nodiscard]] std::uint32_t encode_rate_word(const AxisRate& rate, std::uint32_t min_period_cycles,
                                             const std::string& where = "spi: rate word");
// Period and direction of a word; bit 30 is not the rate's business.
[[nodiscard]] AxisRate decode_rate_word(std::uint32_t word);

// std::invalid_argument for a laser bit without an X word to carry it (a caller bug).
[[nodiscard]] std::vector<std::uint8_t> encode_command(const Command& command, std::uint32_t min_period_cycles);
// nullopt for a frame the FPGA rejects: wrong length or a command byte other than kCmdRates. The laser is bit 30
// of the X word; bit 30 of the other words is ignored.
[[nodiscard]] std::optional<Command> decode_command(const std::vector<std::uint8_t>& bytes, std::size_t n_axes);

[[nodiscard]] std::uint8_t encode_status(const SlaveStatus& status);
[[nodiscard]] SlaveStatus decode_status(std::uint8_t byte);  // fifo_level as sent (saturated)
[[nodiscard]] std::vector<std::uint8_t> encode_feedback(const Feedback& feedback);
// std::invalid_argument when the byte count is not frame_bytes(n_axes) (a caller bug, not user input).
[[nodiscard]] Feedback decode_feedback(const std::vector<std::uint8_t>& bytes, std::size_t n_axes);

// The host's 64-bit position from the 32-bit counter: the previous wide value plus the signed difference
// mod 2^32 (exact as long as an axis moves less than 2^31 steps between two reads).
[[nodiscard]] std::int64_t widen_count(std::int64_t previous, std::int32_t raw);

// Period in FPGA clocks for |steps_per_s| (the sign is the direction's business): clk_hz / |rate| rounded to
// the nearest clock (ties away from zero), so the achieved rate is off by at most half a clock per period.
// 0 steps/s -> 0 (stopped). BadInput with the numbers when the period exceeds kMaxPeriodCycles (rate below
// clk_hz / (2^30 - 1/2)) or is below min_period_cycles (rate above clk_hz / min_period_cycles), or the rate is not finite.
[[nodiscard]] std::uint32_t period_for_rate(double steps_per_s, std::uint32_t clk_hz, std::uint32_t min_period_cycles,
                                            const std::string& where = "spi: rate word");
// Signed rate -> rate word fields (forward for rate >= 0).
[[nodiscard]] AxisRate axis_rate_for(double steps_per_s, std::uint32_t clk_hz, std::uint32_t min_period_cycles,
                                     const std::string& where = "spi: rate word");
// clk_hz / period (the rate the generator produces), 0 for a stopped axis.
[[nodiscard]] double rate_for_period(std::uint32_t period_cycles, std::uint32_t clk_hz);

}  // namespace cnc::spi
