#include "spi/core/spi_bit_faults.hpp"

#include "common/splitmix64.hpp"

namespace cnc::spi {

namespace {
constexpr std::uint64_t kStreamBase = 0x5350'4900;  // "SPI": apart from the other faults' streams
}  // namespace

SpiBitFaults::SpiBitFaults(double ber, std::uint64_t seed)
    : m_ber(ber), m_keys{stream_key(seed, kStreamBase), stream_key(seed, kStreamBase + 1)} {}

std::uint32_t SpiBitFaults::apply(SpiDirection dir, std::vector<std::uint8_t>& frame) {
    const auto d = static_cast<std::size_t>(dir);
    std::uint32_t flipped = 0;
    for (std::size_t k = 0; k < 8 * frame.size(); ++k) {
        if (unit_draw(m_keys[d], m_next_bit[d] + k) < m_ber) {
            frame[k / 8] = static_cast<std::uint8_t>(frame[k / 8] ^ (0x80U >> (k % 8)));
            ++flipped;
        }
    }
    m_next_bit[d] += 8 * frame.size();
    return flipped;
}

}  // namespace cnc::spi
