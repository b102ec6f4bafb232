#include "metrics/driver_timing.hpp"

#include <algorithm>
#include <vector>

namespace cnc::metrics {

namespace {

// Times at which the pin really changes level (repeated writes of the same level are not edges).
std::vector<TimePs> change_times(const EdgeLog& log) {
    std::vector<TimePs> out;
    bool level = log.initial;
    for (const Edge& e : log.edges) {
        if (e.level != level) out.push_back(e.t_ps);
        level = e.level;
    }
    return out;
}

void record(RuleCheck& check, TimePs measured_ps, TimePs at_ps, bool violated) {
    ++check.checked;
    if (!check.min_ps || measured_ps < *check.min_ps) check.min_ps = measured_ps;
    if (!violated) return;
    if (check.violations == 0) check.first_violation_at_ps = at_ps;
    ++check.violations;
}

}  // namespace

std::size_t DriverTimingReport::total_violations() const {
    std::size_t n = 0;
    for (const RuleCheck& r : rules) n += r.violations;
    return n;
}

const char* rule_name(DriverRule rule) {
    switch (rule) {
        case DriverRule::StepHigh: return "step_high";
        case DriverRule::StepLow: return "step_low";
        case DriverRule::DirSetup: return "dir_setup";
        case DriverRule::DirHold: return "dir_hold";
        case DriverRule::Rate: return "rate";
    }
    return "?";
}

double rule_limit_ns(DriverRule rule, const DriverLimits& limits) {
    switch (rule) {
        case DriverRule::StepHigh: return ps_to_ns(limits.step_high_min_ps);
        case DriverRule::StepLow: return ps_to_ns(limits.step_low_min_ps);
        case DriverRule::DirSetup: return ps_to_ns(limits.dir_setup_min_ps);
        case DriverRule::DirHold: return ps_to_ns(limits.dir_hold_min_ps);
        case DriverRule::Rate: return 1e9 / limits.step_rate_max_hz;
    }
    return 0.0;
}

DriverTimingReport check_driver_timing(const EdgeLog& step, const EdgeLog& dir, const DriverLimits& limits) {
    DriverTimingReport report;
    const std::vector<TimePs> dir_changes = change_times(dir);
    std::vector<TimePs> rises;

    std::optional<TimePs> last_rise;
    std::optional<TimePs> last_fall;
    bool level = step.initial;
    for (const Edge& e : step.edges) {
        if (e.level == level) continue;
        level = e.level;
        const TimePs t = e.t_ps;
        if (!level) {
            if (last_rise) {
                const TimePs high = t - *last_rise;
                record(report[DriverRule::StepHigh], high, t, high < limits.step_high_min_ps);
            }
            last_fall = t;
            continue;
        }
        if (last_fall) {
            const TimePs low = t - *last_fall;
            record(report[DriverRule::StepLow], low, t, low < limits.step_low_min_ps);
        }
        if (last_rise) {
            const TimePs interval = t - *last_rise;
            // Compared as interval * f_max < 1 s so that no rounding of 1/f_max enters.
            const bool too_fast = static_cast<double>(interval) * limits.step_rate_max_hz <
                                  static_cast<double>(kPsPerSec);
            record(report[DriverRule::Rate], interval, t, too_fast);
        }
        const auto dir_it = std::upper_bound(dir_changes.begin(), dir_changes.end(), t);
        if (dir_it != dir_changes.begin()) {
            const TimePs setup = t - *std::prev(dir_it);
            record(report[DriverRule::DirSetup], setup, t, setup < limits.dir_setup_min_ps);
        }
        rises.push_back(t);
        last_rise = t;
    }

    for (const TimePs t_dir : dir_changes) {
        const auto rise_it = std::lower_bound(rises.begin(), rises.end(), t_dir);
        if (rise_it == rises.begin()) continue;
        const TimePs hold = t_dir - *std::prev(rise_it);
        record(report[DriverRule::DirHold], hold, t_dir, hold < limits.dir_hold_min_ps);
    }
    return report;
}

}  // namespace cnc::metrics
