#include "metrics/pulse/pulse_runs.hpp"

#include <algorithm>
#include <cmath>

#include "metrics/stats.hpp"

namespace cnc::metrics {

namespace {

constexpr long double kPsPerNsL = 1000.0L;
// A period more than this many times the previous one is a pause, whatever the tolerance.
constexpr double kPauseFactor = 1.5;

double rate_steps_per_s(TimePs t_first, TimePs t_last, std::size_t n) {
    return static_cast<double>(n - 1) * static_cast<double>(kPsPerSec) / static_cast<double>(t_last - t_first);
}

PulseRun measure(const RunInput& in, const AxisEdges& edges, std::size_t axis, EdgeRange r,
                 std::optional<std::size_t> move, std::optional<double> commanded) {
    PulseRun run;
    run.move = move;
    run.edges_range = r;
    const TimePs* t = edges.rising.data() + r.begin;
    const std::size_t n = r.size();
    run.t_first_ps = t[0];
    run.t_last_ps = t[n - 1];
    run.period = period_stats(t, n);
    run.tie = tie_stats(t, n);
    if (n >= 2 && run.t_last_ps > run.t_first_ps) {
        run.rate_achieved_steps_per_s = rate_steps_per_s(run.t_first_ps, run.t_last_ps, n);
        const double steps_per_mm = in.axes[axis].steps_per_mm;
        if (steps_per_mm > 0.0) run.speed_mm_per_min = *run.rate_achieved_steps_per_s / steps_per_mm * 60.0;
    }
    if (commanded && *commanded > 0.0) {
        run.rate_commanded_steps_per_s = commanded;
        if (run.rate_achieved_steps_per_s) {
            run.rate_error_pct = (*run.rate_achieved_steps_per_s - *commanded) / *commanded * 100.0;
        }
    }
    return run;
}

std::optional<double> move_rate(const RunInput& in, std::size_t axis, std::optional<std::size_t> move) {
    if (!move || axis >= in.moves[*move].rate_steps_per_s.size()) return std::nullopt;
    return in.moves[*move].rate_steps_per_s[axis];
}

// One run per rate segment holding edges: [t_k, t_k+1) (a rise at a segment's start is governed by it).
std::vector<PulseRun> segment_runs(const RunInput& in, const AxisEdges& edges, std::size_t axis) {
    const std::vector<RateSegment>& segments = in.rate_segments[axis];
    const MoveTimeline timeline(in.moves);
    std::vector<PulseRun> runs;
    auto first = edges.rising.begin();
    for (std::size_t k = 0; k < segments.size(); ++k) {
        first = std::lower_bound(first, edges.rising.end(), segments[k].t_ps);
        const auto last = k + 1 < segments.size() ? std::lower_bound(first, edges.rising.end(), segments[k + 1].t_ps)
                                                  : edges.rising.end();
        if (first == last) continue;
        const EdgeRange r{static_cast<std::size_t>(first - edges.rising.begin()),
                          static_cast<std::size_t>(last - edges.rising.begin())};
        const std::optional<std::size_t> move = in.moves.empty() ? std::nullopt : timeline.active_at(*first);
        runs.push_back(measure(in, edges, axis, r, move, segments[k].steps_per_s));
    }
    return runs;
}

}  // namespace

std::optional<PeriodStats> period_stats(const TimePs* t, std::size_t n) {
    if (n < 2) return std::nullopt;
    const std::size_t m = n - 1;
    TimePs shortest = t[1] - t[0];
    TimePs longest = shortest;
    for (std::size_t k = 1; k < n; ++k) {
        shortest = std::min(shortest, t[k] - t[k - 1]);
        longest = std::max(longest, t[k] - t[k - 1]);
    }
    const long double mean = static_cast<long double>(t[n - 1] - t[0]) / static_cast<long double>(m);
    long double sum_sq = 0.0L;
    for (std::size_t k = 1; k < n; ++k) {
        const long double d = static_cast<long double>(t[k] - t[k - 1]) - mean;
        sum_sq += d * d;
    }
    PeriodStats s;
    s.mean_ns = static_cast<double>(mean / kPsPerNsL);
    s.std_ns = static_cast<double>(std::sqrt(sum_sq / static_cast<long double>(m)) / kPsPerNsL);
    s.pp_ns = ps_to_ns(longest - shortest);
    return s;
}

namespace {

// The least-squares grid t_k = t_0 + x_mean + slope (k - k_mean) of a run's edges. Centred sums in long double keep
// the residuals of an exact grid below 1e-3 ns even for runs of many seconds.
struct GridFit {
    const TimePs* t;
    long double k_mean;
    long double x_mean;
    long double slope;  // ps per edge

    [[nodiscard]] long double residual_ps(std::size_t k) const {
        const long double x = static_cast<long double>(t[k] - t[0]);  // exact: offsets fit in 64 bits
        return x - x_mean - slope * (static_cast<long double>(k) - k_mean);
    }
};

GridFit fit_grid(const TimePs* t, std::size_t n) {
    const long double nl = static_cast<long double>(n);
    const long double k_mean = (nl - 1.0L) / 2.0L;
    const long double s_kk = nl * (nl * nl - 1.0L) / 12.0L;  // sum of (k - k_mean)^2
    long double sum_x = 0.0L;
    long double s_kx = 0.0L;
    for (std::size_t k = 0; k < n; ++k) {
        const long double x = static_cast<long double>(t[k] - t[0]);
        sum_x += x;
        s_kx += (static_cast<long double>(k) - k_mean) * x;
    }
    return {t, k_mean, sum_x / nl, s_kx / s_kk};
}

}  // namespace

std::optional<TieStats> tie_stats(const TimePs* t, std::size_t n) {
    if (n < 3) return std::nullopt;
    const GridFit fit = fit_grid(t, n);
    MaxRms residuals;
    for (std::size_t k = 0; k < n; ++k) residuals.add(static_cast<double>(fit.residual_ps(k) / kPsPerNsL));
    TieStats s;
    s.period_ns = static_cast<double>(fit.slope / kPsPerNsL);
    s.rms_ns = *residuals.rms();
    s.max_abs_ns = *residuals.max_abs();
    return s;
}

std::vector<double> tie_residuals_ns(const TimePs* t, std::size_t n) {
    std::vector<double> out;
    if (n < 3) return out;
    const GridFit fit = fit_grid(t, n);
    out.reserve(n);
    for (std::size_t k = 0; k < n; ++k) out.push_back(static_cast<double>(fit.residual_ps(k) / kPsPerNsL));
    return out;
}

std::vector<EdgeRange> split_runs(const std::vector<TimePs>& rising, const std::vector<TimePs>& dir_changes,
                                  double tolerance) {
    std::vector<EdgeRange> runs;
    if (rising.empty()) return runs;
    std::size_t begin = 0;
    TimePs sum_ps = 0;
    std::size_t periods = 0;
    TimePs previous_ps = 0;
    for (std::size_t k = 1; k < rising.size(); ++k) {
        const TimePs p = rising[k] - rising[k - 1];
        const auto dir_it = std::upper_bound(dir_changes.begin(), dir_changes.end(), rising[k - 1]);
        bool split = dir_it != dir_changes.end() && *dir_it <= rising[k];
        if (!split && periods > 0) {
            const double mean = static_cast<double>(sum_ps) / static_cast<double>(periods);
            split = std::fabs(static_cast<double>(p) - mean) > tolerance * mean ||
                    static_cast<double>(p) > kPauseFactor * static_cast<double>(previous_ps);
        }
        if (split) {
            runs.push_back({begin, k});
            begin = k;
            sum_ps = 0;
            periods = 0;
        } else {
            sum_ps += p;
            ++periods;
            previous_ps = p;
        }
    }
    runs.push_back({begin, rising.size()});
    return runs;
}

std::vector<PulseRun> axis_runs(const RunInput& in, const EdgeIndex& idx, std::size_t axis) {
    const AxisEdges& edges = idx.axes[axis];
    if (axis < in.rate_segments.size() && !in.rate_segments[axis].empty()) return segment_runs(in, edges, axis);
    std::vector<PulseRun> runs;
    if (in.moves.empty()) {
        for (const EdgeRange& r : split_runs(edges.rising, edges.dir_changes, in.run_split_tolerance)) {
            runs.push_back(measure(in, edges, axis, r, std::nullopt, std::nullopt));
        }
        return runs;
    }
    const std::vector<EdgeRange>& by_move = idx.by_move[axis];
    for (std::size_t m = 0; m < by_move.size(); ++m) {
        if (!by_move[m].empty()) runs.push_back(measure(in, edges, axis, by_move[m], m, move_rate(in, axis, m)));
    }
    return runs;
}

void PulseSummaryFold::add(const PulseRun& r) {
    const std::size_t i = m_out.runs++;
    if (r.period) {
        ++m_out.runs_measured;
        if (!m_out.jitter_std_max_ns || r.period->std_ns > *m_out.jitter_std_max_ns) {
            m_out.jitter_std_max_ns = r.period->std_ns;
            m_out.worst_jitter_run = i;
        }
        keep_max(m_out.jitter_pp_max_ns, r.period->pp_ns);
    }
    if (r.tie) {
        if (!m_out.tie_max_ns || r.tie->max_abs_ns > *m_out.tie_max_ns) {
            m_out.tie_max_ns = r.tie->max_abs_ns;
            m_out.worst_tie_run = i;
        }
        keep_max(m_out.tie_rms_max_ns, r.tie->rms_ns);
        if (r.tie->period_ns > 0.0) keep_max(m_out.tie_max_period_frac, r.tie->max_abs_ns / r.tie->period_ns);
    }
    keep_worst_signed(m_out.rate_error_worst_pct, r.rate_error_pct);
}

AxisPulseSummary summarise_runs(const std::vector<PulseRun>& runs) {
    PulseSummaryFold fold;
    for (const PulseRun& r : runs) fold.add(r);
    return fold.summary();
}

}  // namespace cnc::metrics
