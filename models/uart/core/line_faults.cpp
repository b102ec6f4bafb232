#include "uart/core/line_faults.hpp"

#include <stdexcept>

#include "common/splitmix64.hpp"

namespace cnc::uart {

namespace {
constexpr int kMaxFrameBits = 32;                   // one inversion mask; a UART frame has at most 12 bits
constexpr std::uint64_t kLossDraw = kMaxFrameBits;  // the frame-loss draw follows the bits' draws
}  // namespace

LineFaultDraw::LineFaultDraw(const LineFaultRates& rates, std::uint64_t seed, std::uint64_t line)
    : m_rates(rates), m_key(stream_key(seed, line)) {}

double LineFaultDraw::unit(std::uint64_t frame, std::uint64_t draw) const {
    return unit_draw(m_key, frame * (kMaxFrameBits + 1) + draw);
}

FrameFault LineFaultDraw::frame(std::uint64_t frame, int bits) const {
    if (bits < 1 || bits > kMaxFrameBits) throw std::invalid_argument("LineFaultDraw: frame of 1 .. 32 bits");
    FrameFault f;
    f.lost = m_rates.frame_loss_rate > 0.0 && unit(frame, kLossDraw) < m_rates.frame_loss_rate;
    if (m_rates.ber > 0.0) {
        for (int k = 0; k < bits; ++k) {
            if (unit(frame, static_cast<std::uint64_t>(k)) < m_rates.ber) f.inverted_bits |= 1U << k;
        }
    }
    return f;
}

}  // namespace cnc::uart
