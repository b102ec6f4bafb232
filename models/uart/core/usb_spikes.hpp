// Latency spikes of a USB serial link: now and then the host's USB stack delays a bulk transfer far past its usual
// latency (another driver holding the host controller, the scheduler running something else; a few ms to tens of
// ms on a desktop OS). Drawn per USB frame and direction: a frame carries a spike with probability `rate`, and the
// spike's length is exponential with mean `mean_ps` (the heavy-tailed delays of a busy host, short ones most often).
// Counter-based (SplitMix64 of the seed, the direction and the frame's number), so a frame's spike does not depend on
// which frames carried data before it.
#pragma once
#include <cstdint>

#include "common/units.hpp"

namespace cnc::uart {

struct UsbSpikeRates {
    double rate = 0.0;   // fraction of USB frames that carry a spike, 0 .. 1
    TimePs mean_ps = 0;  // mean extra delay of a spike

    [[nodiscard]] bool any() const { return rate > 0.0 && mean_ps > 0; }
};

class UsbSpikeDraw {
public:
    // `direction`: 0 host to chip (OUT), 1 chip to host (IN).
    UsbSpikeDraw(const UsbSpikeRates& rates, std::uint64_t seed, std::uint64_t direction);

    // The extra delay of the USB frame number `frame` (0 when it carries no spike).
    [[nodiscard]] TimePs extra_ps(std::int64_t frame) const;

private:
    UsbSpikeRates m_rates;
    std::uint64_t m_key;
};

}  // namespace cnc::uart
