// The commanded step rate of every rate word the FPGA applied, for the metrics' pulse runs.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "fpga/spi/spi_board.hpp"
#include "host/servo/core/servo_core.hpp"
#include "metrics/run_input.hpp"

namespace cnc::sim {

// Per axis: one segment per stretch of one applied word (the host resends an unchanged word every period), from
// the edge it governs from, with the mean of the host's requested |rate| over the stretch (0 for a stop word): the
// metrics' runs, whose rate error is then the period rounding. Handed over once a stretch is closed (a different
// word was applied; its mean is final then), every one once the run has `ended`. The applied words are taken
// from the FPGA and folded into the open stretch as they come, so that neither they nor the servo's records
// before first_needed_period() are kept.
class RateSegments {
public:
    [[nodiscard]] std::vector<std::vector<metrics::RateSegment>> take(fpga::SpiBoard& fpga,
                                                                      const host::servo::ServoCore& servo, bool ended);
    // The first servo period whose record a word not taken yet may read (each axis applies its words in frame
    // order, one frame per period).
    [[nodiscard]] std::uint64_t first_needed_period() const;

private:
    struct Stretch {
        TimePs t_ps = 0;  // its first word's
        spi::AxisRate rate;
        double requested_sum_steps_per_s = 0.0;  // of |the host's requested rate|, word by word
        std::size_t words = 0;
    };
    std::array<std::optional<Stretch>, host::servo::kAxes> m_open;
    std::array<std::uint64_t, host::servo::kAxes> m_next_seq{};  // [axis] after the last word's frame
};

}  // namespace cnc::sim
