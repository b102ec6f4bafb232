// Bit errors on the SPI wires: each bit the slave samples on MOSI, and each bit the master samples on MISO, is
// inverted with probability `ber`, independently (crosstalk or ringing on SCLK's sampling edge). A synchronous link
// samples each bit once, so an error is a flipped bit of the frame, not a misframing as on a UART. Counter-based
// (SplitMix64 of the seed, the direction and the bit's number on the link), so a bit's fate does not depend on
// when it is sent.
#pragma once
#include <cstdint>
#include <vector>

namespace cnc::spi {

enum class SpiDirection : std::uint64_t { Mosi = 0, Miso = 1 };

class SpiBitFaults {
public:
    SpiBitFaults(double ber, std::uint64_t seed);

    // Inverts the bits that the draws of `dir` hit in the next frame of that direction (the link's bits numbered
    // over the run, MSB of byte 0 first); returns how many.
    std::uint32_t apply(SpiDirection dir, std::vector<std::uint8_t>& frame);

private:
    double m_ber;
    std::uint64_t m_keys[2];
    std::uint64_t m_next_bit[2] = {0, 0};
};

}  // namespace cnc::spi
