// JSON report of a run: every number carries its unit in its key; absent figures are null.
#include <cstddef>

#include "metrics/metrics.hpp"

namespace cnc::metrics {

namespace {

using nlohmann::json;

template <typename T>
json opt(const std::optional<T>& v) {
    return v ? json(*v) : json(nullptr);
}

json scaled(const std::optional<double>& v, double k) { return v ? json(*v * k) : json(nullptr); }

json limits_json(const DriverLimits& l) {
    return {{"step_high_min_ns", ps_to_ns(l.step_high_min_ps)},
            {"step_low_min_ns", ps_to_ns(l.step_low_min_ps)},
            {"dir_setup_min_ns", ps_to_ns(l.dir_setup_min_ps)},
            {"dir_hold_min_ns", ps_to_ns(l.dir_hold_min_ps)},
            {"step_rate_max_hz", l.step_rate_max_hz}};
}

json driver_json(const DriverTimingReport& r, const DriverLimits& limits) {
    json j = json::object();
    for (const DriverRule rule : kDriverRules) {
        const RuleCheck& c = r[rule];
        j[rule_name(rule)] = {
            {"limit_ns", rule_limit_ns(rule, limits)},
            {"checked", c.checked},
            {"violations", c.violations},
            {"min_ns", c.min_ps ? json(ps_to_ns(*c.min_ps)) : json(nullptr)},
            {"first_violation_s", c.first_violation_at_ps ? json(ps_to_s(*c.first_violation_at_ps)) : json(nullptr)}};
    }
    j["violations_total"] = r.total_violations();
    return j;
}

json run_json(const PulseRun& r) {
    json j = {{"move", opt(r.move)},
              {"edges", r.edges()},
              {"first_edge", r.edges_range.begin},
              {"t_first_ps", r.t_first_ps},
              {"t_last_ps", r.t_last_ps},
              {"period_mean_ns", nullptr},
              {"jitter_std_ns", nullptr},
              {"jitter_pp_ns", nullptr},
              {"tie_period_ns", nullptr},
              {"tie_rms_ns", nullptr},
              {"tie_max_ns", nullptr},
              {"tie_rms_period_frac", nullptr},
              {"tie_max_period_frac", nullptr},
              {"rate_achieved_steps_per_s", opt(r.rate_achieved_steps_per_s)},
              {"rate_commanded_steps_per_s", opt(r.rate_commanded_steps_per_s)},
              {"rate_error_pct", opt(r.rate_error_pct)},
              {"speed_mm_per_min", opt(r.speed_mm_per_min)}};
    if (r.period) {
        j["period_mean_ns"] = r.period->mean_ns;
        j["jitter_std_ns"] = r.period->std_ns;
        j["jitter_pp_ns"] = r.period->pp_ns;
    }
    if (r.tie) {
        j["tie_period_ns"] = r.tie->period_ns;
        j["tie_rms_ns"] = r.tie->rms_ns;
        j["tie_max_ns"] = r.tie->max_abs_ns;
        if (r.tie->period_ns > 0.0) {
            j["tie_rms_period_frac"] = r.tie->rms_ns / r.tie->period_ns;
            j["tie_max_period_frac"] = r.tie->max_abs_ns / r.tie->period_ns;
        }
    }
    return j;
}

json axis_json(const AxisMetrics& a, const DriverLimits& limits) {
    json runs = json::array();
    for (const PulseRun& r : a.runs) runs.push_back(run_json(r));
    return {{"axis", a.name},
            {"step_signal", a.step_signal},
            {"dir_signal", a.dir_signal},
            {"rising_edges", a.rising_edges},
            {"falling_edges", a.falling_edges},
            {"dir_changes", a.dir_changes},
            {"net_steps", a.net_steps},
            {"travel_mm", opt(a.travel_mm)},
            {"net_mm", opt(a.net_mm)},
            {"unattributed_edges", a.unattributed_edges},
            {"runs_count", a.pulse.runs},
            {"runs_measured", a.pulse.runs_measured},
            {"jitter_std_max_ns", opt(a.pulse.jitter_std_max_ns)},
            {"jitter_pp_max_ns", opt(a.pulse.jitter_pp_max_ns)},
            {"worst_jitter_run", opt(a.pulse.worst_jitter_run)},
            {"tie_rms_max_ns", opt(a.pulse.tie_rms_max_ns)},
            {"tie_max_ns", opt(a.pulse.tie_max_ns)},
            {"tie_max_period_frac", opt(a.pulse.tie_max_period_frac)},
            {"worst_tie_run", opt(a.pulse.worst_tie_run)},
            {"rate_error_worst_pct", opt(a.pulse.rate_error_worst_pct)},
            {"sync_max_ns", opt(a.sync_max_abs_ns)},
            {"sync_unmatched_edges", opt(a.sync_unmatched_edges)},
            {"driver_timing", driver_json(a.driver, limits)},
            {"runs", runs}};
}

json move_json(const MoveMetrics& m) {
    json sync = json::array();
    for (const auto& s : m.sync_max_abs_ns) sync.push_back(opt(s));
    return {{"index", m.index},
            {"line", m.line},
            {"rapid", m.rapid},
            {"feed_mm_per_min", m.feed_mm_per_min},
            {"steps_commanded", m.steps_commanded},
            {"steps_emitted", m.steps_emitted},
            {"t_first_edge_ps", opt(m.t_first_edge_ps)},
            {"t_last_edge_ps", opt(m.t_last_edge_ps)},
            {"sync_max_ns", sync},
            {"motion_time_s", opt(m.timing.motion_time_s)},
            {"achieved_feed_mm_per_min", opt(m.timing.achieved_feed_mm_per_min)},
            {"feed_error_pct", opt(m.timing.feed_error_pct)},
            {"tool_samples", m.path.samples},
            {"contour_max_um", opt(m.path.contour_max_um)},
            {"following_max_um", opt(m.path.following_max_um)},
            {"following_rms_um", opt(m.path.following_rms_um)},
            {"endpoint_vs_command_um", opt(m.path.endpoint_vs_command_um)},
            {"endpoint_vs_program_um", opt(m.path.endpoint_vs_program_um)}};
}

json job_json(const RunMetrics& m) {
    const TimingResult& t = m.timing;
    json gaps = json::array();
    for (const DeadGap& g : t.gaps) {
        gaps.push_back({{"after_move", m.moves[g.after_move].index},
                        {"before_move", m.moves[g.before_move].index},
                        {"dead_ms", ps_to_s(g.dead_ps) * 1e3}});
    }
    return {{"job_time_s", t.job_time_s},
            {"motion_time_s", opt(t.motion_time_s)},
            {"lead_in_ms", opt(t.lead_in_ms)},
            {"tail_ms", opt(t.tail_ms)},
            {"dead_gaps", t.gaps.size()},
            {"dead_total_ms", opt(t.dead_total_ms)},
            {"dead_mean_ms", opt(t.dead_mean_ms)},
            {"dead_max_ms", opt(t.dead_max_ms)},
            {"dead_times", gaps}};
}

json laser_json(const std::optional<LaserResult>& l) {
    if (!l) return nullptr;
    return {{"on_ms", l->on_ms},
            {"dwell_ms", opt(l->dwell_ms)},
            {"dwell_intervals", l->dwell_intervals},
            {"dwell_longest_ms", opt(l->dwell_longest_ms)},
            {"dwell_longest_at_s", opt(l->dwell_longest_at_s)},
            {"on_in_rapid_ms", opt(l->on_in_rapid_ms)}};
}

}  // namespace

nlohmann::json to_json(const RunMetrics& m) {
    json axes = json::array();
    for (const AxisMetrics& a : m.axes) axes.push_back(axis_json(a, m.limits));
    json moves = json::array();
    for (const MoveMetrics& mv : m.moves) moves.push_back(move_json(mv));
    const PulseTotals& p = m.pulse;
    const PathResult& path = m.path;
    const TimingResult& t = m.timing;
    return {{"limits", limits_json(m.limits)},
            {"pulse",
             {{"jitter_std_max_ns", opt(p.jitter_std_max_ns)},
              {"jitter_pp_max_ns", opt(p.jitter_pp_max_ns)},
              {"tie_rms_max_ns", opt(p.tie_rms_max_ns)},
              {"tie_max_ns", opt(p.tie_max_ns)},
              {"tie_max_period_frac", opt(p.tie_max_period_frac)},
              {"rate_error_worst_pct", opt(p.rate_error_worst_pct)},
              {"sync_max_ns", opt(p.sync_max_abs_ns)},
              {"sync_max_us", scaled(p.sync_max_abs_ns, 1e-3)},
              {"driver_violations", p.driver_violations}}},
            {"run_split_tolerance", m.with_moves ? json(nullptr) : json(m.run_split_tolerance)},
            {"axes", axes},
            {"moves", moves},
            {"path",
             {{"tool_samples", path.samples},
              {"contour_max_um", opt(path.contour_max_um)},
              {"contour_rms_um", opt(path.contour_rms_um)},
              {"following_max_um", opt(path.following_max_um)},
              {"following_rms_um", opt(path.following_rms_um)},
              {"endpoint_vs_command_max_um", opt(path.endpoint_vs_command_max_um)},
              {"endpoint_vs_program_max_um", opt(path.endpoint_vs_program_max_um)},
              {"job_end_um", opt(path.job_end_um)}}},
            {"feed",
             {{"cutting_moves_measured", t.feed_moves},
              {"feed_error_mean_pct", opt(t.feed_error_mean_pct)},
              {"feed_error_mean_abs_pct", opt(t.feed_error_mean_abs_pct)},
              {"feed_error_max_abs_pct", opt(t.feed_error_max_abs_pct)}}},
            {"job", job_json(m)},
            {"laser", laser_json(m.laser)}};
}

}  // namespace cnc::metrics
