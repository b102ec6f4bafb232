#include "architectures/spi_fpga/rate_segments.hpp"

#include <algorithm>
#include <cmath>

namespace cnc::sim {

std::vector<std::vector<metrics::RateSegment>> RateSegments::take(fpga::SpiBoard& fpga,
                                                                  const host::servo::ServoCore& servo, bool ended) {
    std::vector<std::vector<metrics::RateSegment>> out(host::servo::kAxes);
    for (std::size_t a = 0; a < host::servo::kAxes; ++a) {
        std::optional<Stretch>& open = m_open[a];
        const auto close = [&] {
            const double mean = open->rate.period_cycles == 0
                                    ? 0.0
                                    : open->requested_sum_steps_per_s / static_cast<double>(open->words);
            out[a].push_back({open->t_ps, mean});
        };
        for (const fpga::AppliedRate& w : fpga.take_applied(a)) {
            // A stretch of one word (the same period and direction reloaded period after period) is one STEP train.
            if (open && !(w.rate == open->rate)) {
                close();
                open.reset();
            }
            if (!open) open = Stretch{w.t_ps, w.rate, 0.0, 0};
            if (w.seq < servo.periods()) {
                open->requested_sum_steps_per_s += std::fabs(servo.record(w.seq).axes[a].requested_steps_per_s);
            }
            ++open->words;
            m_next_seq[a] = w.seq + 1;
        }
        if (ended && open) {
            close();
            open.reset();
        }
    }
    return out;
}

std::uint64_t RateSegments::first_needed_period() const {
    return *std::min_element(m_next_seq.begin(), m_next_seq.end());
}

}  // namespace cnc::sim
