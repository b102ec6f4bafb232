// Faults on one asynchronous serial line, drawn per frame: bit errors at a bit error rate (each bit of a frame,
// start and stop bits included, inverted with probability `ber`, independently) and frames lost whole (the line
// stays idle for the frame, as when a driver or a connector drops out for a byte). The draw is counter-based
// (SplitMix64 of the seed, the line and the frame's number on it), so a run is reproducible whatever else it
// draws, and a frame's fate does not depend on when it is sent.
#pragma once
#include <cstdint>

namespace cnc::uart {

struct LineFaultRates {
    double ber = 0.0;              // bit error rate, 0 .. 0.5
    double frame_loss_rate = 0.0;  // fraction of frames lost whole, 0 .. 1

    [[nodiscard]] bool any() const { return ber > 0.0 || frame_loss_rate > 0.0; }
};

struct FrameFault {
    bool lost = false;
    std::uint32_t inverted_bits = 0;  // bit k set: the frame's bit k (0 = start bit) is inverted

    [[nodiscard]] bool hit() const { return lost || inverted_bits != 0; }
};

class LineFaultDraw {
public:
    // `line` tells apart the lines that share a seed (each direction of a link).
    LineFaultDraw(const LineFaultRates& rates, std::uint64_t seed, std::uint64_t line);

    // The fate of the line's frame number `frame` (0, 1, ...) of `bits` bits (at most 32).
    [[nodiscard]] FrameFault frame(std::uint64_t frame, int bits) const;

private:
    [[nodiscard]] double unit(std::uint64_t frame, std::uint64_t draw) const;

    LineFaultRates m_rates;
    std::uint64_t m_key;
};

}  // namespace cnc::uart
