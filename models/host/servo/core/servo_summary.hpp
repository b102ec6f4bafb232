// What the spi-fpga report says of the servo periods without listing them, in bounded memory (docs/streaming.md): the
// period counts by mode, the wake-up latency's min/mean/max and the first rows of the rate staircase, folded period by
// period so that the records need not be kept for it (`--detail` lists every period and keeps them).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/units.hpp"
#include "host/servo/core/servo_core.hpp"

namespace cnc::host::servo {

struct Wakeup {
    TimePs t_ps = 0;        // actual wake-up
    TimePs latency_ps = 0;  // after the nominal n * period
};

// One row of the staircase excerpt: a period's wake-up and what each axis was asked for and sent.
struct StaircaseRow {
    TimePs t_ps = 0;
    std::array<double, kAxes> requested_steps_per_s{};
    std::array<spi::AxisRate, kAxes> word{};
};

class ServoSummary {
public:
    // Rows of the staircase excerpt, from the first period that sends a running word.
    static constexpr std::size_t kStaircaseRows = 12;

    void add(const PeriodRecord& rec, const Wakeup& wakeup);

    [[nodiscard]] std::uint64_t periods() const { return m_periods; }
    [[nodiscard]] std::uint64_t tracking_periods() const { return m_tracking; }
    [[nodiscard]] std::uint64_t landing_periods() const { return m_landing; }
    [[nodiscard]] TimePs latency_min_ps() const { return m_latency_min_ps; }
    [[nodiscard]] TimePs latency_max_ps() const { return m_latency_max_ps; }
    [[nodiscard]] double latency_mean_ps() const;  // 0 before the first period
    [[nodiscard]] const std::vector<StaircaseRow>& staircase() const { return m_staircase; }

private:
    std::uint64_t m_periods = 0;
    std::uint64_t m_tracking = 0;
    std::uint64_t m_landing = 0;
    TimePs m_latency_min_ps = 0;
    TimePs m_latency_max_ps = 0;
    long double m_latency_sum_ps = 0.0L;  // long double: exact over 10^7 periods of integer ps
    std::vector<StaircaseRow> m_staircase;
};

}  // namespace cnc::host::servo
