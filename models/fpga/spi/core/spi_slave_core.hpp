// spi_slave logic (seed 004 §5.1.1: mode 0; SS active low, §5.2), clocked by the FPGA clock. SCLK, MOSI and SS pass a
// 2-FF synchroniser; the first flip-flop samples all three at the same edge e and the logic acts on that
// sample at edge e + kSpiSyncStages (its registers change their outputs then):
//   SS fell        -> FrameStart: bit counter cleared, the reply (status + step counters) loaded, MISO = bit 0
//   SCLK rose (SS low)  -> MOSI as sampled at e shifted in (no output)
//   SCLK fell (SS low)  -> MisoShift: MISO = next reply bit
//   SS rose        -> FrameEnd: the bits shifted in are handed over (pushed to the FIFO if a whole frame)
// Reset values of the sampled pins: SS high, SCLK low, MOSI low. The core is fed samples in edge order.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace cnc::fpga {

struct SlaveEvent {
    enum class Kind { FrameStart, MisoShift, FrameEnd };
    Kind kind = Kind::FrameStart;
    std::int64_t edge = 0;           // edge at which the logic acts (registered outputs change)
    std::size_t miso_bit = 0;        // MisoShift: index of the reply bit now on MISO
    std::vector<std::uint8_t> mosi;  // FrameEnd: bytes shifted in, MSB first (a partial last byte is dropped)
    std::size_t mosi_bits = 0;       // FrameEnd: rising SCLK edges seen while SS was low
};

class SpiSlaveCore {
public:
    // The pin levels the first synchroniser stage captured at clock edge `edge`; appends the logic's reaction.
    void sample(std::int64_t edge, bool ss, bool sclk, bool mosi, std::vector<SlaveEvent>& out);
    // Transaction path (no wires): SS fell / rose at a time whose first sampling edge is `edge`.
    [[nodiscard]] SlaveEvent select(std::int64_t edge);
    [[nodiscard]] SlaveEvent deselect(std::int64_t edge, const std::vector<std::uint8_t>& mosi);

private:
    bool m_ss = true;
    bool m_sclk = false;
    std::vector<std::uint8_t> m_bytes;
    std::size_t m_bits = 0;
    std::size_t m_falls = 0;
};

}  // namespace cnc::fpga
