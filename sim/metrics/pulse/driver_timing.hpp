// DRV8825 STEP/DIR timing rules checked on recorded edges, so that any trace (simulated or captured
// by a logic analyser) is judged against the same datasheet limits (TI SLVSA73).
#pragma once
#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "common/edge_log.hpp"
#include "common/units.hpp"
#include "mechanics/core/drv8825_timing.hpp"

namespace cnc::metrics {

// The limits are the DRV8825 model's own (one definition of the data-sheet numbers).
using DriverLimits = mech::DriverLimits;

enum class DriverRule : std::size_t { StepHigh, StepLow, DirSetup, DirHold, Rate };
inline constexpr std::size_t kDriverRuleCount = 5;
inline constexpr std::array<DriverRule, kDriverRuleCount> kDriverRules{
    DriverRule::StepHigh, DriverRule::StepLow, DriverRule::DirSetup, DriverRule::DirHold, DriverRule::Rate};

// One rule on one axis. The measured quantity is a time (pulse width, setup, hold, or the interval
// between consecutive rising edges for the rate rule); a violation is a measurement below the limit.
struct RuleCheck {
    std::size_t checked = 0;  // measurements taken
    std::size_t violations = 0;
    std::optional<TimePs> min_ps;                 // smallest measurement: the worst case when violations > 0
    std::optional<TimePs> first_violation_at_ps;  // time of the STEP/DIR edge that ended the first violation
};

struct DriverTimingReport {
    std::array<RuleCheck, kDriverRuleCount> rules;

    [[nodiscard]] const RuleCheck& operator[](DriverRule r) const { return rules[static_cast<std::size_t>(r)]; }
    [[nodiscard]] RuleCheck& operator[](DriverRule r) { return rules[static_cast<std::size_t>(r)]; }
    [[nodiscard]] std::size_t total_violations() const;
};

[[nodiscard]] const char* rule_name(DriverRule rule);  // step_high, step_low, dir_setup, dir_hold, rate
// Limit as a time: the rate limit is the shortest allowed interval between rising edges (4 us at 250 kHz).
[[nodiscard]] double rule_limit_ns(DriverRule rule, const DriverLimits& limits);

// The driver timing of one axis checked window by window, for a run whose edge logs are dropped as it goes: the
// checker's state (levels, last rise, fall and DIR change) carries over, so the report equals one check of the
// whole logs. Each add() gives the edges of both pins in one time window, later than the previous window's; both
// pins must be cut at the same instant, so that a DIR change and a STEP rise at one time stay in one window and
// keep their order (DIR first).
class DriverTimingStream {
public:
    DriverTimingStream(const DriverLimits& limits, bool step_initial, bool dir_initial);

    void add(const std::vector<Edge>& step_edges, const std::vector<Edge>& dir_edges);
    [[nodiscard]] DriverTimingReport report() const;

private:
    mech::Drv8825TimingChecker m_checker;
};

// Runs the DRV8825 model's checker (mech::Drv8825TimingChecker) over the recorded edges, so a trace is judged
// exactly as the simulated driver judged it. A DIR change at the very instant of a STEP rising edge is a
// setup violation of 0 ps for that step (the driver may latch either direction), not also a hold violation.
[[nodiscard]] DriverTimingReport check_driver_timing(const EdgeLog& step, const EdgeLog& dir,
                                                     const DriverLimits& limits);

}  // namespace cnc::metrics
