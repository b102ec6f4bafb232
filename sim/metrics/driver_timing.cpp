#include "metrics/driver_timing.hpp"


namespace cnc::metrics {


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
    mech::Drv8825TimingChecker checker(limits);
    checker.set_initial_levels(step.initial, dir.initial);
    // Merge the two pins in time order; on a tie DIR goes first, so a simultaneous change counts as setup 0.
    auto s = step.edges.begin();
    auto d = dir.edges.begin();
    while (s != step.edges.end() || d != dir.edges.end()) {
        if (d != dir.edges.end() && (s == step.edges.end() || d->t_ps <= s->t_ps)) {
            checker.on_dir(d->t_ps, d->level);
            ++d;
        } else {
            checker.on_step(s->t_ps, s->level);
            ++s;
        }
    }
    // DriverRule and mech::TimingRule list the rules in the same order.
    DriverTimingReport report;
    for (std::size_t i = 0; i < kDriverRuleCount; ++i) {
        const mech::RuleStats& r = checker.stats().rules[i];
        report.rules[i] = RuleCheck{static_cast<std::size_t>(r.checks), static_cast<std::size_t>(r.violations),
                                    r.worst_ps, r.first_violation_ps};
    }
    return report;
}

}  // namespace cnc::metrics
