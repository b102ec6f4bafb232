#include "uart/core/usb_spikes.hpp"

#include <cmath>

#include "common/splitmix64.hpp"

namespace cnc::uart {

namespace {
constexpr std::uint64_t kStreamBase = 0x5553'4200;  // "USB": apart from the line faults' streams 0 and 1
}  // namespace

UsbSpikeDraw::UsbSpikeDraw(const UsbSpikeRates& rates, std::uint64_t seed, std::uint64_t direction)
    : m_rates(rates), m_key(stream_key(seed, kStreamBase + direction)) {}

TimePs UsbSpikeDraw::extra_ps(std::int64_t frame) const {
    if (!m_rates.any() || frame < 0) return 0;
    const auto n = static_cast<std::uint64_t>(frame);
    if (unit_draw(m_key, 2 * n) >= m_rates.rate) return 0;
    // Inverse of the exponential distribution's CDF; 1 - u is in (0, 1].
    const double u = unit_draw(m_key, 2 * n + 1);
    return static_cast<TimePs>(std::llround(-std::log1p(-u) * static_cast<double>(m_rates.mean_ps)));
}

}  // namespace cnc::uart
