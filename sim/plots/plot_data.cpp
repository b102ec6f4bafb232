#include "plots/plot_data.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <optional>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "metrics/commanded.hpp"
#include "metrics/path/path_accuracy.hpp"
#include "metrics/pulse/edge_index.hpp"
#include "metrics/pulse/pulse_runs.hpp"
#include "metrics/timing/job_gaps.hpp"
#include "metrics/timing/programmed_moves.hpp"
#include "plots/arch_plot.hpp"

namespace cnc::sim {

namespace {

namespace fs = std::filesystem;
using metrics::RunInput;

// Sizes that keep a plot readable and its SVG small whatever the job's length; the figures themselves (maxima)
// survive the thinning because each window keeps its worst sample.
constexpr std::size_t kMaxToolRows = 6000;
// The zoom panels draw only what falls in their window, from a file of their own that keeps ten times the rows:
// on the 104 s sample drawing (about 494,000 samples, one per step) a row every 9 samples, at most 9 microsteps
// (0.06 mm at 160 steps/mm) per axis.
constexpr std::size_t kMaxZoomRows = 60000;
constexpr std::size_t kTimeBins = 2000;
constexpr double kArcPointSpacingMm = 0.05;
// 5 ms: a 160 steps/mm axis makes >= 1 step in it above 1.25 mm/s. On a job longer than kTimeBins x 5 ms (10 s) the
// grid is coarser than that, and the window widens to the grid step: a 5 ms window sampled every 50 ms would show
// where in its ringing each sample fell instead of the speed between samples.
constexpr TimePs kVelocityWindowPs = 5 * kPsPerMs;

std::ofstream open(const fs::path& file, const std::string& header) {
    std::ofstream out(file);
    if (!out) throw std::runtime_error("cannot write " + file.string());
    out << "# " << header << '\n';
    return out;
}

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
}

bool same_point(geom::Vec2 a, geom::Vec2 b) {
    return geom::distance(a, b) < 1e-9;
}

// Returns the larger side of the box the programmed path fills, mm (the zoomed inset's scale).
double write_program(const RunInput& in, const fs::path& dir) {
    std::ofstream feed = open(dir / "program.dat", "x_mm y_mm: programmed feed moves");
    std::ofstream rapid = open(dir / "rapids.dat", "x_mm y_mm: programmed rapids");
    std::ofstream ends = open(dir / "moves.dat",
                              "move line kind end_x_mm end_y_mm end_z_mm center_x_mm center_y_mm: where each "
                              "programmed move ends (an arc's centre, nan for a line)");
    std::optional<geom::Vec2> feed_end, rapid_end;
    geom::Box box{{1e300, 1e300}, {-1e300, -1e300}};
    for (std::size_t i = 0; i < in.moves.size(); ++i) {
        if (i > 0 && metrics::same_programmed_move(in.moves[i - 1], in.moves[i])) continue;  // chords of one arc
        const geom::Segment& seg = in.moves[i].path;
        const metrics::ProgrammedEnd e = metrics::programmed_end(in.moves[i]);
        ends << (in.moves[i].programmed >= 0 ? in.moves[i].programmed + 1 : in.moves[i].index) << ' '
             << in.moves[i].line << ' ' << metrics::to_string(e.kind) << ' ' << num(e.x_mm) << ' ' << num(e.y_mm) << ' '
             << num(e.z_mm) << ' ' << num(e.center_x_mm.value_or(std::nan(""))) << ' '
             << num(e.center_y_mm.value_or(std::nan(""))) << '\n';
        std::ofstream& out = in.moves[i].rapid ? rapid : feed;
        std::optional<geom::Vec2>& end = in.moves[i].rapid ? rapid_end : feed_end;
        if (end && !same_point(*end, seg.start)) out << '\n';
        const double length = seg.length_mm();
        const int pieces = seg.is_arc ? std::max(8, static_cast<int>(std::ceil(length / kArcPointSpacingMm))) : 1;
        for (int k = (end && same_point(*end, seg.start)) ? 1 : 0; k <= pieces; ++k) {
            const geom::Vec2 p = seg.point_at(length * k / pieces);
            out << num(p.x_mm) << ' ' << num(p.y_mm) << '\n';
        }
        end = seg.end;
        const geom::Box b = seg.bounds();
        box = {{std::min(box.min.x_mm, b.min.x_mm), std::min(box.min.y_mm, b.min.y_mm)},
               {std::max(box.max.x_mm, b.max.x_mm), std::max(box.max.y_mm, b.max.y_mm)}};
    }
    return in.moves.empty() ? 0.0 : std::max(box.max.x_mm - box.min.x_mm, box.max.y_mm - box.min.y_mm);
}

struct ToolRow {
    std::size_t sample = 0;
    double travel_mm = 0.0;
    metrics::SampleError error;
};

// Thins the tool samples to at most `max_rows`: of each window of consecutive samples, the one of largest contour
// error.
class WorstPerWindow {
public:
    WorstPerWindow(std::size_t samples, std::size_t max_rows)
        : m_samples(samples), m_window((samples + max_rows - 1) / max_rows) {}
    // The row to write when `row` closes its window.
    std::optional<ToolRow> add(const ToolRow& row) {
        if (!m_open || row.error.contour_um > m_kept.error.contour_um) m_kept = row;
        m_open = true;
        if ((row.sample + 1) % m_window != 0 && row.sample + 1 != m_samples) return std::nullopt;
        m_open = false;
        return m_kept;
    }

private:
    std::size_t m_samples;
    std::size_t m_window;
    ToolRow m_kept;
    bool m_open = false;
};

// The samples of largest contour error: over the feed moves (over any move if there are only rapids), where the
// zoom panels look, since a controller's own rapid path (seed 003's dog-leg G0) would hide where the cutting
// differs; and over every move, the report's contour error max (docs/metrics.md: rapids are included).
struct WorstRows {
    std::optional<ToolRow> cut;
    std::optional<ToolRow> any;
};

WorstRows write_tool(const RunInput& in, const metrics::EdgeIndex& idx, const fs::path& dir) {
    std::ofstream out = open(dir / "tool.dat", "t_s x_mm y_mm travel_mm contour_um following_um");
    std::ofstream zoom = open(dir / "tool_zoom.dat", "x_mm y_mm: the tool path at the zoom panels' resolution");
    if (in.tool.empty() || in.moves.empty()) return {};
    const metrics::MoveTimeline timeline(in.moves);
    WorstPerWindow rows(in.tool.size(), kMaxToolRows);
    WorstPerWindow zoom_rows(in.tool.size(), kMaxZoomRows);
    ToolRow worst, worst_any;
    bool worst_rapid = false;
    double travel = 0.0;
    for (std::size_t i = 0; i < in.tool.size(); ++i) {
        if (i > 0) travel += geom::distance(in.tool[i - 1].pos, in.tool[i].pos);
        const ToolRow row{i, travel, metrics::sample_error(in, idx, timeline, i)};
        const bool rapid = in.moves[row.error.move].rapid;
        if (i == 0 || (worst_rapid && !rapid) ||
            (rapid == worst_rapid && row.error.contour_um > worst.error.contour_um)) {
            worst = row;
            worst_rapid = rapid;
        }
        if (i == 0 || row.error.contour_um > worst_any.error.contour_um) worst_any = row;
        if (const std::optional<ToolRow> kept = rows.add(row)) {
            const ToolSample& s = in.tool[kept->sample];
            out << num(ps_to_s(s.t_ps)) << ' ' << num(s.pos.x_mm) << ' ' << num(s.pos.y_mm) << ' '
                << num(kept->travel_mm) << ' ' << num(kept->error.contour_um) << ' ' << num(kept->error.following_um)
                << '\n';
        }
        if (const std::optional<ToolRow> kept = zoom_rows.add(row)) {
            const ToolSample& s = in.tool[kept->sample];
            zoom << num(s.pos.x_mm) << ' ' << num(s.pos.y_mm) << '\n';
        }
    }
    return {worst, worst_any};
}

// Keeps, per time bin, the value of largest magnitude.
class WorstPerBin {
public:
    WorstPerBin(TimePs t0_ps, TimePs t1_ps)
        : m_t0_ps(t0_ps), m_bin_ps(std::max<TimePs>(1, (t1_ps - t0_ps) / kTimeBins)) {}
    void add(TimePs t_ps, double v) {
        const TimePs bin = (t_ps - m_t0_ps) / m_bin_ps;
        auto [it, fresh] = m_bins.try_emplace(bin, t_ps, v);
        if (!fresh && std::fabs(v) > std::fabs(it->second.second)) it->second = {t_ps, v};
    }
    void write(std::ostream& out) const {
        for (const auto& [bin, tv] : m_bins) out << num(ps_to_s(tv.first)) << ' ' << num(tv.second) << '\n';
    }

private:
    TimePs m_t0_ps;
    TimePs m_bin_ps;
    std::map<TimePs, std::pair<TimePs, double>> m_bins;
};

void write_pulses(const RunInput& in, const metrics::RunMetrics& m, const metrics::EdgeIndex& idx,
                  const fs::path& dir) {
    for (std::size_t a = 0; a < m.axes.size(); ++a) {
        const std::vector<TimePs>& rising = idx.axes[a].rising;
        std::map<std::int64_t, std::size_t> periods_ns;
        WorstPerBin tie(in.t_job_start_ps, std::max(in.t_job_end_ps, rising.empty() ? 0 : rising.back()));
        for (const metrics::PulseRun& r : m.axes[a].runs) {
            const TimePs* t = rising.data() + r.edges_range.begin;
            const std::size_t n = r.edges();
            for (std::size_t k = 1; k < n; ++k) ++periods_ns[std::llround(ps_to_ns(t[k] - t[k - 1]))];
            const std::vector<double> residuals = metrics::tie_residuals_ns(t, n);
            for (std::size_t k = 0; k < residuals.size(); ++k) tie.add(t[k], residuals[k]);
        }
        std::ofstream p = open(dir / ("periods_" + m.axes[a].name + ".dat"), "period_us count");
        for (const auto& [ns, count] : periods_ns) p << num(static_cast<double>(ns) / 1000.0) << ' ' << count << '\n';
        std::ofstream t = open(dir / ("tie_" + m.axes[a].name + ".dat"), "t_s tie_ns");
        tie.write(t);
    }
}

// The commanded path speed: the planner's trajectory where there is one, else each move's F from its first STEP for
// its motion time (the uniform motion the metrics measure following error against).
class CommandedSpeed {
public:
    CommandedSpeed(const RunInput& in, const metrics::RunMetrics& m) : m_in(in) {
        m.moves.for_each([this](const metrics::MoveMetrics& mv) {
            if (!mv.t_first_edge_ps || !mv.timing.motion_time_s) return;
            m_spans.push_back({*mv.t_first_edge_ps, *mv.t_first_edge_ps + s_to_ps(*mv.timing.motion_time_s),
                               mv.feed_mm_per_min / kSecondsPerMinute});
        });
    }
    double at(TimePs t_ps) {  // called with rising t_ps
        if (m_in.commanded) return geom::norm(metrics::commanded_at(*m_in.commanded, t_ps).vel_mm_per_s);
        while (m_next < m_spans.size() && m_spans[m_next].t_end_ps <= t_ps) ++m_next;
        if (m_next < m_spans.size() && m_spans[m_next].t_begin_ps <= t_ps) return m_spans[m_next].speed_mm_per_s;
        return 0.0;
    }

private:
    struct Span {
        TimePs t_begin_ps, t_end_ps;
        double speed_mm_per_s;
    };
    const RunInput& m_in;
    std::vector<Span> m_spans;
    std::size_t m_next = 0;
};

void write_velocity(const RunInput& in, const metrics::RunMetrics& m, const fs::path& dir) {
    std::ofstream out = open(dir / "velocity.dat", "t_s commanded_mm_per_s carriage_mm_per_s");
    if (in.t_job_end_ps <= in.t_job_start_ps) return;
    const TimePs dt = std::max<TimePs>(kPsPerMs, (in.t_job_end_ps - in.t_job_start_ps) / kTimeBins);
    std::vector<double> travel(in.tool.size(), 0.0);
    for (std::size_t i = 1; i < in.tool.size(); ++i)
        travel[i] = travel[i - 1] + geom::distance(in.tool[i - 1].pos, in.tool[i].pos);
    // The tool stands still between samples: its travel at t is that of the last sample at or before t.
    const auto travel_at = [&](TimePs t_ps) {
        const auto it = std::upper_bound(in.tool.begin(), in.tool.end(), t_ps,
                                         [](TimePs t, const ToolSample& s) { return t < s.t_ps; });
        return it == in.tool.begin() ? 0.0 : travel[static_cast<std::size_t>(it - in.tool.begin()) - 1];
    };
    CommandedSpeed commanded(in, m);
    const TimePs window = std::max(kVelocityWindowPs, dt);
    const TimePs half = window / 2;
    for (TimePs t = in.t_job_start_ps; t <= in.t_job_end_ps; t += dt) {
        const double carriage = in.tool.empty() ? 0.0 : (travel_at(t + half) - travel_at(t - half)) / ps_to_s(2 * half);
        out << num(ps_to_s(t)) << ' ' << num(commanded.at(t)) << ' ' << num(carriage) << '\n';
    }
}

struct DeadTimeRows {
    std::vector<std::string> causes;  // in the order of the columns (none unless every gap has its split)
    std::size_t between = 0, inside = 0;
};

// Every gap of the job, between and inside the programmed moves, in order: a move's gaps (the one that leads into
// it, then those between its pieces) are consecutive rows.
DeadTimeRows write_dead_time(const metrics::RunMetrics& m, const ArchRun& run, const fs::path& dir) {
    std::map<std::size_t, const GapCauses*> by_piece;
    for (const GapCauses& g : run.gap_causes) by_piece[g.after_piece] = &g;
    const std::vector<metrics::JobGap> gaps = metrics::job_gaps(m.moves, m.pieces);
    // The architecture's split is of the gap from one piece to the next: a gap across a piece that made no step
    // is none of its gaps.
    const auto split_of = [&by_piece](const metrics::JobGap& g) -> const GapCauses* {
        const auto it = by_piece.find(g.after_piece);
        return it != by_piece.end() && g.before_piece == g.after_piece + 1 ? it->second : nullptr;
    };
    const bool split = !gaps.empty() && std::all_of(gaps.begin(), gaps.end(), split_of);
    DeadTimeRows rows;
    if (split) {
        for (const auto& part : by_piece.begin()->second->parts_ms) rows.causes.push_back(part.first);
    }
    std::string header = "gap move inside total_ms";
    for (const std::string& c : rows.causes) header += ' ' + c + "_ms";
    std::ofstream out = open(dir / "dead_time.dat", header);
    for (std::size_t k = 0; k < gaps.size(); ++k) {
        const metrics::JobGap& g = gaps[k];
        ++(g.inside() ? rows.inside : rows.between);
        out << k + 1 << ' ' << g.before_move + 1 << ' ' << (g.inside() ? 1 : 0) << ' '
            << num(static_cast<double>(g.dead_ps) / static_cast<double>(kPsPerMs));
        if (split) {
            for (const auto& part : split_of(g)->parts_ms) out << ' ' << num(part.second);
        }
        out << '\n';
    }
    return rows;
}

nlohmann::json write_series(const ArchRun& run, const fs::path& dir) {
    nlohmann::json list = nlohmann::json::array();
    for (std::size_t k = 0; k < run.series.size(); ++k) {
        const TimeSeries& s = run.series[k];
        const std::string file = "series_" + std::to_string(k) + ".dat";
        std::ofstream out = open(dir / file, "t_s value: " + s.quantity + ", axis " + s.axis);
        for (const auto& [t, v] : s.points) out << num(ps_to_s(t)) << ' ' << num(v) << '\n';
        nlohmann::json marks = nlohmann::json::array();
        for (const SeriesMark& mark : s.marks) marks.push_back({{"value", mark.value}, {"label", mark.label}});
        list.push_back({{"file", file}, {"quantity", s.quantity}, {"axis", s.axis}, {"marks", marks}});
    }
    return list;
}

}  // namespace

void write_plot_data(const std::string& architecture, const ArchRun& run, const metrics::RunMetrics& m,
                     const fs::path& dir) {
    fs::create_directories(dir);
    const RunInput& in = run.input;
    const metrics::EdgeIndex idx = metrics::index_edges(in);
    const double extent_mm = write_program(in, dir);
    const WorstRows worst = write_tool(in, idx, dir);
    write_pulses(in, m, idx, dir);
    write_velocity(in, m, dir);
    const DeadTimeRows gaps = write_dead_time(m, run, dir);
    nlohmann::json meta = {{"architecture", architecture},
                           {"axes", nlohmann::json::array()},
                           {"causes", gaps.causes},
                           {"gaps_between_moves", gaps.between},
                           {"gaps_inside_moves", gaps.inside},
                           {"series", write_series(run, dir)},
                           {"arch_plots", write_arch_plots(run.plots, dir)},
                           {"job_time_s", ps_to_s(in.t_job_end_ps - in.t_job_start_ps)},
                           {"program_extent_mm", extent_mm}};
    for (const metrics::AxisMetrics& a : m.axes) meta["axes"].push_back(a.name);
    const auto where = [&in](const std::optional<ToolRow>& row) -> nlohmann::json {
        if (!row) return nullptr;
        const geom::Vec2 p = in.tool[row->sample].pos;
        const metrics::MoveSpec& move = in.moves[row->error.move];
        return {{"x_mm", p.x_mm},
                {"y_mm", p.y_mm},
                {"contour_um", row->error.contour_um},
                {"line", move.line},
                {"rapid", move.rapid}};
    };
    meta["worst_contour"] = where(worst.cut);
    meta["contour_max"] = where(worst.any);
    std::ofstream out(dir / "meta.json");
    if (!out) throw std::runtime_error("cannot write " + (dir / "meta.json").string());
    out << meta.dump(2) << '\n';
}

}  // namespace cnc::sim
