#include "metrics/pulse/sync_error.hpp"

#include <cmath>
#include <cstdlib>

#include "metrics/commanded.hpp"
#include "metrics/stats.hpp"

namespace cnc::metrics {

namespace {

SyncResult sync_to_trajectory(const RunInput& in, const EdgeIndex& idx) {
    SyncResult out;
    const std::size_t n_axes = idx.axes.size();
    out.axis_max_abs_ns.assign(n_axes, std::nullopt);
    out.move_axis_max_abs_ns.assign(in.moves.size(), std::vector<std::optional<double>>(n_axes));
    out.axis_unmatched_edges.assign(n_axes, std::nullopt);
    out.move_axis_unmatched_edges.assign(in.moves.size(), std::vector<std::size_t>(n_axes, 0));
    const CommandedTrajectory& c = *in.commanded;
    for (std::size_t a = 0; a < n_axes && a < kPathAxes; ++a) {
        const double steps_per_mm = in.axes[a].steps_per_mm;
        if (steps_per_mm <= 0.0) continue;
        std::size_t& unmatched = out.axis_unmatched_edges[a].emplace(0);
        const AxisEdges& edges = idx.axes[a];
        if (edges.rising.empty()) continue;
        // Only a crossing within the sync window of an edge can match it.
        const StepCrossings crossings = step_crossings(c, a, steps_per_mm, edges.rising.front() - c.sync_window_ps,
                                                       edges.rising.back() + c.sync_window_ps);
        std::vector<std::optional<double>> error_ns(edges.rising.size());
        std::int64_t count = a < c.count_before_steps.size() ? c.count_before_steps[a] : 0;
        for (std::size_t k = 0; k < edges.rising.size(); ++k) {
            count += edges.rising_sign[k];
            const std::optional<TimePs> t = crossings.nearest(count, edges.rising_sign[k], edges.rising[k]);
            if (!t || std::llabs(edges.rising[k] - *t) > in.commanded->sync_window_ps) {
                ++unmatched;
                continue;
            }
            error_ns[k] = ps_to_ns(edges.rising[k] - *t);
        }
        for (std::size_t m = 0; m < in.moves.size(); ++m) {
            const EdgeRange r = idx.by_move[a][m];
            for (std::size_t k = r.begin; k < r.end; ++k) {
                if (!error_ns[k]) {
                    ++out.move_axis_unmatched_edges[m][a];
                    continue;
                }
                const double e = std::fabs(*error_ns[k]);
                keep_max(out.move_axis_max_abs_ns[m][a], e);
                keep_max(out.axis_max_abs_ns[a], e);
                keep_max(out.max_abs_ns, e);
            }
        }
    }
    return out;
}

}  // namespace

SyncResult compute_sync(const RunInput& in, const EdgeIndex& idx) {
    if (in.commanded && !in.moves.empty()) return sync_to_trajectory(in, idx);
    SyncResult out;
    const std::size_t n_axes = idx.axes.size();
    out.axis_max_abs_ns.assign(n_axes, std::nullopt);
    out.move_axis_max_abs_ns.assign(in.moves.size(), std::vector<std::optional<double>>(n_axes));
    for (std::size_t m = 0; m < in.moves.size(); ++m) {
        if (!idx.move_first_edge_ps[m]) continue;
        const TimePs t0 = *idx.move_first_edge_ps[m];
        for (std::size_t a = 0; a < n_axes && a < in.moves[m].rate_steps_per_s.size(); ++a) {
            const double rate = in.moves[m].rate_steps_per_s[a];
            const EdgeRange r = idx.by_move[a][m];
            if (rate <= 0.0 || r.empty()) continue;
            const long double period_ps = static_cast<long double>(kPsPerSec) / rate;
            double worst = 0.0;
            for (std::size_t k = 0; k < r.size(); ++k) {
                const long double ideal = period_ps * static_cast<long double>(k);
                const long double actual = static_cast<long double>(idx.axes[a].rising[r.begin + k] - t0);
                worst = std::max(worst, static_cast<double>(std::fabs(actual - ideal) / 1000.0L));
            }
            out.move_axis_max_abs_ns[m][a] = worst;
            keep_max(out.axis_max_abs_ns[a], worst);
            keep_max(out.max_abs_ns, worst);
        }
    }
    return out;
}

}  // namespace cnc::metrics
