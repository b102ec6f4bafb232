#include "metrics/pulse/driver_timing.hpp"

namespace cnc::metrics {

std::size_t DriverTimingReport::total_violations() const {
    std::size_t n = 0;
    for (const RuleCheck& r : rules) n += r.violations;
    return n;
}

const char* rule_name(DriverRule rule) {
    switch (rule) {
        case DriverRule::StepHigh:
            return "step_high";
        case DriverRule::StepLow:
            return "step_low";
        case DriverRule::DirSetup:
            return "dir_setup";
        case DriverRule::DirHold:
            return "dir_hold";
        case DriverRule::Rate:
            return "rate";
    }
    return "?";
}

double rule_limit_ns(DriverRule rule, const DriverLimits& limits) {
    switch (rule) {
        case DriverRule::StepHigh:
            return ps_to_ns(limits.step_high_min_ps);
        case DriverRule::StepLow:
            return ps_to_ns(limits.step_low_min_ps);
        case DriverRule::DirSetup:
            return ps_to_ns(limits.dir_setup_min_ps);
        case DriverRule::DirHold:
            return ps_to_ns(limits.dir_hold_min_ps);
        case DriverRule::Rate:
            return 1e9 / limits.step_rate_max_hz;
    }
    return 0.0;
}

DriverTimingStream::DriverTimingStream(const DriverLimits& limits, bool step_initial, bool dir_initial)
    : m_checker(limits) {
    m_checker.set_initial_levels(step_initial, dir_initial);
}

void DriverTimingStream::add(const std::vector<Edge>& step_edges, const std::vector<Edge>& dir_edges) {
    // Merge the two pins in time order; on a tie DIR goes first, so a simultaneous change counts as setup 0.
    auto s = step_edges.begin();
    auto d = dir_edges.begin();
    while (s != step_edges.end() || d != dir_edges.end()) {
        if (d != dir_edges.end() && (s == step_edges.end() || d->t_ps <= s->t_ps)) {
            m_checker.on_dir(d->t_ps, d->level);
            ++d;
        } else {
            m_checker.on_step(s->t_ps, s->level);
            ++s;
        }
    }
}

DriverTimingReport DriverTimingStream::report() const {
    // DriverRule and mech::TimingRule list the rules in the same order.
    DriverTimingReport report;
    for (std::size_t i = 0; i < kDriverRuleCount; ++i) {
        const mech::RuleStats& r = m_checker.stats().rules[i];
        report.rules[i] = RuleCheck{static_cast<std::size_t>(r.checks), static_cast<std::size_t>(r.violations),
                                    r.worst_ps, r.first_violation_ps};
    }
    return report;
}

DriverTimingReport check_driver_timing(const EdgeLog& step, const EdgeLog& dir, const DriverLimits& limits) {
    DriverTimingStream stream(limits, step.initial, dir.initial);
    stream.add(step.edges, dir.edges);
    return stream.report();
}

}  // namespace cnc::metrics
