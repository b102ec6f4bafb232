// DRV8825 STEP/DIR timing requirements and an incremental checker of a pin trace against them.
#pragma once
#include <array>
#include <cstdint>
#include <optional>

#include "common/units.hpp"

namespace cnc::mech {

// TI SLVSA73 timing requirements (seed 000 §5.2.4 quotes the 1.9 us STEP high time).
struct DriverLimits {
    TimePs step_high_min_ps = 1'900'000;  // tWH(STEP) 1.9 us
    TimePs step_low_min_ps = 1'900'000;   // tWL(STEP) 1.9 us
    TimePs dir_setup_min_ps = 650'000;    // tSU(STEP) 650 ns: DIR stable before STEP rises
    TimePs dir_hold_min_ps = 650'000;     // tH(STEP) 650 ns: DIR stable after STEP rises
    double step_rate_max_hz = 250'000;    // fSTEP 250 kHz
};

enum class TimingRule { StepHigh, StepLow, DirSetup, DirHold, StepRate };
inline constexpr std::size_t kTimingRuleCount = 5;

struct RuleStats {
    std::int64_t checks = 0;
    std::int64_t violations = 0;
    std::optional<TimePs> worst_ps;  // smallest measured value (a time, or the rise-to-rise period for StepRate)
    std::optional<TimePs> first_violation_ps;  // time of the edge that completed the first violation
};

struct TimingStats {
    std::array<RuleStats, kTimingRuleCount> rules{};
    [[nodiscard]] const RuleStats& operator[](TimingRule r) const { return rules[static_cast<std::size_t>(r)]; }
    [[nodiscard]] std::int64_t total_violations() const;
};

// Feed every STEP and DIR level change in time order. Measurements:
//   StepHigh  at each STEP fall: time since the rise.
//   StepLow   at each STEP rise: time since the previous fall (not for the first pulse).
//   DirSetup  at each STEP rise: time since the last DIR change (if DIR ever changed). A DIR change at the
//             same instant as a rise is a setup of 0 whichever of the two is fed first (SystemC runs the
//             DIR and STEP processes of one time stamp in either order).
//   DirHold   at each DIR change: time since the last STEP rise (if any).
//   StepRate  at each STEP rise: the period since the previous rise; a violation when 1 / period > fSTEP max.
// The pins start low (the driver's internal pull-downs) unless set_initial_levels says otherwise; calls that
// repeat the current level are not edges and are ignored.
class Drv8825TimingChecker {
public:
    explicit Drv8825TimingChecker(const DriverLimits& limits = {}) : m_limits(limits) {}

    void set_initial_levels(bool step, bool dir) {
        m_step = step;
        m_dir = dir;
    }
    void on_step(TimePs t_ps, bool level);
    void on_dir(TimePs t_ps, bool level);
    [[nodiscard]] const TimingStats& stats() const { return m_stats; }
    [[nodiscard]] const DriverLimits& limits() const { return m_limits; }

private:
    void measure(TimingRule rule, TimePs t_ps, TimePs value_ps, bool violated);

    DriverLimits m_limits;
    TimingStats m_stats;
    bool m_step = false;
    bool m_dir = false;
    std::optional<TimePs> m_last_rise_ps;
    std::optional<TimePs> m_last_fall_ps;
    std::optional<TimePs> m_last_dir_change_ps;
};

}  // namespace cnc::mech
