// JSON report of a run: every number carries its unit in its key; absent figures are null. The default report
// grows with the moves only; the pulse runs (one per piece and axis, or per rate word: per servo period), the
// dead-time gaps and the executed pieces of the programmed moves come with `detail`.
#include <cstddef>
#include <functional>
#include <map>
#include <ostream>
#include <string>

#include <nlohmann/json.hpp>

#include "common/rounding.hpp"
#include "metrics/metrics.hpp"
#include "metrics/report/report.hpp"
#include "metrics/timing/job_gaps.hpp"

namespace cnc::metrics {

namespace {

using nlohmann::json;

template <typename T>
json opt(const std::optional<T>& v) {
    return v ? json(*v) : json(nullptr);
}

json scaled(const std::optional<double>& v, double k) {
    return v ? json(*v * k) : json(nullptr);
}

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

json axis_json(const AxisMetrics& a, const DriverLimits& limits, bool detail) {
    json j = {{"axis", a.name},
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
              {"driver_timing", driver_json(a.driver, limits)}};
    if (detail) {
        json runs = json::array();
        for (const PulseRun& r : a.runs) runs.push_back(run_json(r));
        j["runs"] = std::move(runs);
    }
    return j;
}

json rounded_opt(const std::optional<double>& v, double per_unit) {
    return v ? json(rounded(*v, per_unit)) : json(nullptr);
}

// Per-unit resolutions of the per-move figures (common/rounding.hpp rounded()).
constexpr double kToTheNm = 1e3;            // um
constexpr double kToThePs = 1e3;            // ns
constexpr double kToTheNs = 1e9;            // s
constexpr double kToThousandths = 1e3;      // mm/min
constexpr double kToPartsPerMillion = 1e4;  // %

// A per-move field; per-axis fields take the axis too. `detail`: written only with --detail. `programmed_only`: a
// column of programmed moves only (their timing, move_timing.hpp), not in the pieces' table.
struct MoveColumn {
    const char* key;
    bool detail;
    json (*value)(const MoveMetrics&);
    bool programmed_only = false;
};
struct AxisColumn {
    const char* key;
    bool detail;
    json (*value)(const MoveMetrics&, std::size_t axis);
};

// The default keeps what a move is looked up for (where it is in the program and in time, its steps, and the
// figures the worst-moves lists rank by); --detail adds the rest.
const MoveColumn kMoveColumns[] = {
    {"index", false, [](const MoveMetrics& m) { return json(m.index); }},
    {"line", false, [](const MoveMetrics& m) { return json(m.line); }},
    {"rapid", false, [](const MoveMetrics& m) { return json(m.rapid()); }},
    {"kind", false, [](const MoveMetrics& m) { return json(to_string(m.programmed.kind)); }},
    {"end_x_mm", false, [](const MoveMetrics& m) { return json(m.programmed.x_mm); }},
    {"end_y_mm", false, [](const MoveMetrics& m) { return json(m.programmed.y_mm); }},
    {"end_z_mm", false, [](const MoveMetrics& m) { return json(m.programmed.z_mm); }},
    {"center_x_mm", false, [](const MoveMetrics& m) { return opt(m.programmed.center_x_mm); }},
    {"center_y_mm", false, [](const MoveMetrics& m) { return opt(m.programmed.center_y_mm); }},
    {"feed_mm_per_min", false, [](const MoveMetrics& m) { return json(rounded(m.feed_mm_per_min, kToThousandths)); }},
    {"pieces", false, [](const MoveMetrics& m) { return json(m.pieces); }, true},
    {"t_first_edge_ps", false, [](const MoveMetrics& m) { return opt(m.t_first_edge_ps); }},
    {"t_last_edge_ps", true, [](const MoveMetrics& m) { return opt(m.t_last_edge_ps); }},
    {"motion_time_s", false, [](const MoveMetrics& m) { return rounded_opt(m.timing.motion_time_s, kToTheNs); }, true},
    {"achieved_feed_mm_per_min", true,
     [](const MoveMetrics& m) { return rounded_opt(m.timing.achieved_feed_mm_per_min, kToThousandths); }, true},
    {"feed_error_pct", false,
     [](const MoveMetrics& m) { return rounded_opt(m.timing.feed_error_pct, kToPartsPerMillion); }, true},
    {"tool_samples", true, [](const MoveMetrics& m) { return json(m.path.samples); }},
    {"contour_max_um", false, [](const MoveMetrics& m) { return rounded_opt(m.path.contour_max_um, kToTheNm); }},
    {"following_max_um", false, [](const MoveMetrics& m) { return rounded_opt(m.path.following_max_um, kToTheNm); }},
    {"following_rms_um", true, [](const MoveMetrics& m) { return rounded_opt(m.path.following_rms_um, kToTheNm); }},
    {"endpoint_vs_command_um", true,
     [](const MoveMetrics& m) { return rounded_opt(m.path.endpoint_vs_command_um, kToTheNm); }},
    {"endpoint_vs_program_um", true,
     [](const MoveMetrics& m) { return rounded_opt(m.path.endpoint_vs_program_um, kToTheNm); }},
};
const AxisColumn kAxisColumns[] = {
    {"steps_commanded", false, [](const MoveMetrics& m, std::size_t a) { return json(m.steps_commanded[a]); }},
    {"steps_emitted", false, [](const MoveMetrics& m, std::size_t a) { return json(m.steps_emitted[a]); }},
    {"sync_max_ns", true,
     [](const MoveMetrics& m, std::size_t a) { return rounded_opt(m.sync_max_abs_ns[a], kToThePs); }},
};

// The moves as columns, one array per field in move order (per axis: one per axis name), so that a long job's
// moves are a few lines of the report file (report_text.cpp) instead of one record of 20 keys per move.
// `programmed`: the programmed moves; else the pieces (no timing columns).
void for_each_move(const MoveRecords& moves, const std::function<void(const MoveMetrics&)>& visit) {
    moves.for_each(visit);
}
void for_each_move(const std::vector<MoveMetrics>& moves, const std::function<void(const MoveMetrics&)>& visit) {
    for (const MoveMetrics& mv : moves) visit(mv);
}

template <typename Moves>
json moves_json(const RunMetrics& m, const Moves& moves, bool detail, bool programmed) {
    json cols = json::object();
    for (const MoveColumn& c : kMoveColumns) {
        if ((c.detail && !detail) || (c.programmed_only && !programmed)) continue;
        json values = json::array();
        for_each_move(moves, [&](const MoveMetrics& mv) { values.push_back(c.value(mv)); });
        cols[c.key] = std::move(values);
    }
    for (const AxisColumn& c : kAxisColumns) {
        if (c.detail && !detail) continue;
        json per_axis = json::object();
        for (std::size_t a = 0; a < m.axes.size(); ++a) {
            json values = json::array();
            for_each_move(moves, [&](const MoveMetrics& mv) { values.push_back(c.value(mv, a)); });
            per_axis[m.axes[a].name] = std::move(values);
        }
        cols[c.key] = std::move(per_axis);
    }
    return cols;
}

// The writers of an object's members by key, in the order nlohmann keeps an object's keys (std::string's), each
// handed its value's depth; written as report_text() writes an object.
using MemberWriters = std::map<std::string, std::function<void(int depth)>>;

void write_object(std::ostream& out, const MemberWriters& members, int depth) {
    if (members.empty()) {
        out << "{}";
        return;
    }
    out << "{\n";
    bool first = true;
    for (const auto& [key, write] : members) {
        if (!first) out << ",\n";
        first = false;
        out << std::string(static_cast<std::size_t>((depth + 1) * kReportIndent), ' ') << json(key).dump() << ": ";
        write(depth + 1);
    }
    out << '\n' << std::string(static_cast<std::size_t>(depth * kReportIndent), ' ') << '}';
}

// A column on one line, as report_text() writes an array of plain values: one pass over the records.
void write_column(std::ostream& out, const MoveRecords& moves, const std::function<json(const MoveMetrics&)>& value) {
    out << '[';
    bool first = true;
    moves.for_each([&](const MoveMetrics& mv) {
        if (!first) out << ',';
        first = false;
        out << value(mv).dump();
    });
    out << ']';
}

// Each figure's worst moves (worst_moves.hpp): index, G-code line and the figure, rounded as in the moves.
json worst_json(const RunMetrics& m) {
    const WorstMoves& w = m.worst;
    const struct {
        const char* key;
        const std::vector<RankedMove>& list;
        double per_unit;
    } figures[] = {{"contour_max_um", w.contour, kToTheNm},
                   {"following_max_um", w.following, kToTheNm},
                   {"feed_error_pct", w.feed, kToPartsPerMillion}};
    json out = json::object();
    for (const auto& f : figures) {
        json list = json::array();
        for (const RankedMove& r : f.list) {
            list.push_back({{"move", r.index}, {"line", r.line}, {f.key, rounded(r.value, f.per_unit)}});
        }
        out[f.key] = std::move(list);
    }
    return out;
}

json job_json(const RunMetrics& m, bool detail) {
    const TimingResult& t = m.timing;
    // Without moves (analyze) the job is only the span of the traced edges: no lead-in, tail or gaps to count.
    const auto of_moves = [&m](const json& v) { return m.with_moves ? v : json(nullptr); };
    json j = {{"job_time_s", t.job_time_s},
              {"motion_time_s", opt(t.motion_time_s)},
              {"lead_in_ms", of_moves(opt(t.lead_in_ms))},
              {"tail_ms", of_moves(opt(t.tail_ms))},
              {"dead_gaps", of_moves(t.gap_count)},
              {"dead_total_ms", opt(t.dead_total_ms)},
              {"dead_mean_ms", opt(t.dead_mean_ms)},
              {"dead_max_ms", opt(t.dead_max_ms)},
              {"dead_inside_gaps", of_moves(t.inside_gap_count)},
              {"dead_inside_total_ms", opt(t.dead_inside_total_ms)},
              {"dead_inside_mean_ms", opt(t.dead_inside_mean_ms)},
              {"dead_inside_max_ms", opt(t.dead_inside_max_ms)},
              {"dead_all_total_ms", opt(t.dead_all_total_ms)}};
    if (detail) {
        json gaps = json::array();
        for (const DeadGap& g : dead_gaps(m.moves)) {
            gaps.push_back({{"after_move", m.moves.at(g.after_move).index},
                            {"before_move", m.moves.at(g.before_move).index},
                            {"dead_ms", ps_to_s(g.dead_ps) * 1e3}});
        }
        j["dead_times"] = std::move(gaps);
        json inside = json::array();
        for (const JobGap& g : job_gaps(m.moves, m.pieces)) {
            if (!g.inside()) continue;
            inside.push_back({{"move", m.moves.at(g.after_move).index},
                              {"after_piece", g.after_piece + 1},
                              {"before_piece", g.before_piece + 1},
                              {"dead_ms", ps_to_s(g.dead_ps) * 1e3}});
        }
        j["dead_times_inside"] = std::move(inside);
    }
    return j;
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

void write_move_columns(std::ostream& out, const RunMetrics& m, bool detail, int depth) {
    MemberWriters columns;
    for (const MoveColumn& c : kMoveColumns) {
        if (c.detail && !detail) continue;
        columns[c.key] = [&out, &m, &c](int) { write_column(out, m.moves, c.value); };
    }
    for (const AxisColumn& c : kAxisColumns) {
        if (c.detail && !detail) continue;
        columns[c.key] = [&out, &m, &c](int axes_depth) {
            MemberWriters per_axis;
            for (std::size_t a = 0; a < m.axes.size(); ++a) {
                per_axis[m.axes[a].name] = [&out, &m, &c, a](int) {
                    write_column(out, m.moves, [&c, a](const MoveMetrics& mv) { return c.value(mv, a); });
                };
            }
            write_object(out, per_axis, axes_depth);
        };
    }
    write_object(out, columns, depth);
}

nlohmann::json to_json(const RunMetrics& m, bool detail, MoveColumns columns) {
    json axes = json::array();
    for (const AxisMetrics& a : m.axes) axes.push_back(axis_json(a, m.limits, detail));
    const PulseTotals& p = m.pulse;
    const PathResult& path = m.path;
    const TimingResult& t = m.timing;
    json out = {
        {"limits", limits_json(m.limits)},
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
        {"run_split_tolerance", m.with_moves || m.runs_per_rate_segment ? json(nullptr) : json(m.run_split_tolerance)},
        {"axes", axes},
        {"moves", columns == MoveColumns::InJson ? moves_json(m, m.moves, detail, true) : json(nullptr)},
        {"worst_moves", worst_json(m)},
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
          {"cutting_moves_below_feed", t.below_feed_moves},
          {"feed_error_mean_pct", opt(t.feed_error_mean_pct)},
          {"feed_error_mean_abs_pct", opt(t.feed_error_mean_abs_pct)},
          {"feed_error_max_abs_pct", opt(t.feed_error_max_abs_pct)}}},
        {"job", job_json(m, detail)},
        {"laser", laser_json(m.laser)}};
    if (detail) out["pieces"] = moves_json(m, m.pieces, detail, false);
    return out;
}

}  // namespace cnc::metrics
