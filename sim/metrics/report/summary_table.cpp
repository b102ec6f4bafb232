// The text summary the CLI prints: totals and worst cases per metric family, per axis where it matters, and the
// worst moves. The per-move records are in the JSON report (the per-run ones with --detail).
#include <algorithm>
#include <string>

#include "metrics/metrics.hpp"
#include "metrics/report/report.hpp"
#include "metrics/report/text_table.hpp"
#include "metrics/stats.hpp"
#include "metrics/timing/worst_moves.hpp"

namespace cnc::metrics {

namespace {

std::string count(std::size_t n) {
    return std::to_string(n);
}

std::optional<double> times(std::optional<double> v, double k) {
    return v ? std::optional<double>(*v * k) : std::nullopt;
}

std::string edges_section(const RunMetrics& m) {
    TextTable t({"axis", "step", "dir", "rising", "falling", "dir changes", "net steps", "travel [mm]", "net [mm]"});
    for (const AxisMetrics& a : m.axes) {
        t.add_row({a.name, a.step_signal, a.dir_signal, count(a.rising_edges), count(a.falling_edges),
                   count(a.dir_changes), std::to_string(a.net_steps), fixed(a.travel_mm, 4), fixed(a.net_mm, 4)});
    }
    return t.render("Edges");
}

std::string pulse_section(const RunMetrics& m) {
    TextTable t({"axis", "runs", "jitter std max [ns]", "jitter p-p max [ns]", "TIE rms max [ns]", "TIE max [ns]",
                 "TIE max [% period]", "rate error worst [%]", "sync max [us]"});
    const auto row = [&](const std::string& name, std::size_t runs, std::optional<double> std_ns,
                         std::optional<double> pp_ns, std::optional<double> tie_rms, std::optional<double> tie_max,
                         std::optional<double> tie_frac, std::optional<double> rate, std::optional<double> sync_ns) {
        t.add_row({name, count(runs), fixed(std_ns, 3), fixed(pp_ns, 3), fixed(tie_rms, 3), fixed(tie_max, 3),
                   fixed(times(tie_frac, 100.0), 4), fixed(rate, 4), fixed(times(sync_ns, 1e-3), 3)});
    };
    std::size_t runs = 0;
    for (const AxisMetrics& a : m.axes) {
        const AxisPulseSummary& p = a.pulse;
        row(a.name, p.runs, p.jitter_std_max_ns, p.jitter_pp_max_ns, p.tie_rms_max_ns, p.tie_max_ns,
            p.tie_max_period_frac, p.rate_error_worst_pct, a.sync_max_abs_ns);
        runs += p.runs;
    }
    const PulseTotals& p = m.pulse;
    row("all", runs, p.jitter_std_max_ns, p.jitter_pp_max_ns, p.tie_rms_max_ns, p.tie_max_ns, p.tie_max_period_frac,
        p.rate_error_worst_pct, p.sync_max_abs_ns);
    if (m.runs_per_rate_segment) return t.render("Pulse timing (one run per commanded rate word and axis)");
    return t.render(m.with_moves ? "Pulse timing (one run per move and axis)"
                                 : "Pulse timing (runs split by period change)");
}

std::string driver_section(const RunMetrics& m) {
    TextTable t({"axis", "rule", "limit [ns]", "min seen [ns]", "checked", "violations"});
    for (const AxisMetrics& a : m.axes) {
        for (const DriverRule rule : kDriverRules) {
            const RuleCheck& c = a.driver[rule];
            const std::optional<double> min_ns = c.min_ps ? std::optional<double>(ps_to_ns(*c.min_ps)) : std::nullopt;
            t.add_row({a.name, rule_name(rule), fixed(rule_limit_ns(rule, m.limits), 1), fixed(min_ns, 1),
                       count(c.checked), count(c.violations)});
        }
    }
    return t.render("Driver timing (DRV8825), total violations " + count(m.pulse.driver_violations));
}

std::string path_section(const RunMetrics& m) {
    const PathResult& p = m.path;
    TextTable t({"tool samples", "contour max [um]", "contour rms [um]", "following max [um]", "following rms [um]",
                 "endpoint vs command max [um]", "endpoint vs program max [um]", "job end [um]"});
    t.add_row({count(p.samples), fixed(p.contour_max_um, 3), fixed(p.contour_rms_um, 3), fixed(p.following_max_um, 3),
               fixed(p.following_rms_um, 3), fixed(p.endpoint_vs_command_max_um, 3),
               fixed(p.endpoint_vs_program_max_um, 3), fixed(p.job_end_um, 3)});
    return t.render("Path accuracy");
}

std::string feed_section(const RunMetrics& m) {
    const TimingResult& f = m.timing;
    TextTable t(
        {"cutting moves", "below F", "feed error mean [%]", "feed error mean abs [%]", "feed error max abs [%]"});
    t.add_row({count(f.feed_moves), count(f.below_feed_moves), fixed(f.feed_error_mean_pct, 4),
               fixed(f.feed_error_mean_abs_pct, 4), fixed(f.feed_error_max_abs_pct, 4)});
    return t.render("Feed (cutting moves)");
}

// The worst moves of each figure side by side, one rank per row; "-" where a figure has fewer moves (or none).
std::string worst_section(const RunMetrics& m) {
    const WorstMoves& w = m.worst;
    TextTable t({"rank", "contour max [um]", "move", "line", "following max [um]", "move", "line", "feed error [%]",
                 "move", "line"});
    const auto add = [&](std::vector<std::string>& row, const std::vector<RankedMove>& list, std::size_t rank,
                         int decimals) {
        if (rank >= list.size()) {
            row.insert(row.end(), {"-", "-", "-"});
            return;
        }
        const RankedMove& r = list[rank];
        row.insert(row.end(), {fixed(r.value, decimals), std::to_string(r.index), std::to_string(r.line)});
    };
    const std::size_t rows = std::max({w.contour.size(), w.following.size(), w.feed.size(), std::size_t{1}});
    for (std::size_t rank = 0; rank < rows; ++rank) {
        std::vector<std::string> row = {count(rank + 1)};
        add(row, w.contour, rank, 3);
        add(row, w.following, rank, 3);
        add(row, w.feed, rank, 4);
        t.add_row(std::move(row));
    }
    return t.render("Worst moves (move index, G-code line)");
}

std::string job_section(const RunMetrics& m) {
    const TimingResult& j = m.timing;
    TextTable t({"job [s]", "motion [s]", "lead-in [ms]", "tail [ms]"});
    // Without moves (analyze) the job is only the span of the traced edges: no lead-in, tail or gaps to count.
    const auto of_moves = [&m](std::optional<double> v) { return m.with_moves ? v : std::nullopt; };
    const auto gaps = [&m](std::size_t n) { return m.with_moves ? count(n) : "-"; };
    t.add_row({fixed(j.job_time_s, 6), fixed(j.motion_time_s, 6), fixed(of_moves(j.lead_in_ms), 3),
               fixed(of_moves(j.tail_ms), 3)});
    TextTable d({"dead time", "gaps", "total [ms]", "mean [ms]", "max [ms]"});
    d.add_row({"between moves", gaps(j.gap_count), fixed(j.dead_total_ms, 3), fixed(j.dead_mean_ms, 3),
               fixed(j.dead_max_ms, 3)});
    d.add_row({"inside moves", gaps(j.inside_gap_count), fixed(j.dead_inside_total_ms, 3),
               fixed(j.dead_inside_mean_ms, 3), fixed(j.dead_inside_max_ms, 3)});
    const std::size_t all_gaps = j.gap_count + j.inside_gap_count;
    std::optional<double> all_mean_ms, all_max_ms;
    if (all_gaps > 0) all_mean_ms = *j.dead_all_total_ms / static_cast<double>(all_gaps);
    keep_max(all_max_ms, j.dead_max_ms);
    keep_max(all_max_ms, j.dead_inside_max_ms);
    d.add_row({"total", gaps(all_gaps), fixed(j.dead_all_total_ms, 3), fixed(all_mean_ms, 3), fixed(all_max_ms, 3)});
    return t.render(m.with_moves ? "Job timing" : "Job timing (the span of the traced edges)") + '\n' +
           d.render("Dead time (between programmed moves; inside them, between their pieces)");
}

std::string laser_section(const LaserResult& l) {
    TextTable t(
        {"on [ms]", "dwell [ms]", "dwell stretches", "longest dwell [ms]", "longest at [s]", "on in rapid [ms]"});
    t.add_row({fixed(l.on_ms, 3), fixed(l.dwell_ms, 3), count(l.dwell_intervals), fixed(l.dwell_longest_ms, 3),
               fixed(l.dwell_longest_at_s, 6), fixed(l.on_in_rapid_ms, 3)});
    return t.render("Laser");
}

}  // namespace

std::string summary_table(const RunMetrics& m) {
    std::string out = edges_section(m) + '\n' + pulse_section(m) + '\n' + driver_section(m);
    if (m.with_moves && m.with_tool) out += '\n' + path_section(m);
    if (m.with_moves) out += '\n' + feed_section(m) + '\n' + worst_section(m);
    out += '\n' + job_section(m);
    if (m.laser) out += '\n' + laser_section(*m.laser);
    return out;
}

}  // namespace cnc::metrics
