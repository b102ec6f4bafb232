#include "metrics/move_timing.hpp"

#include <algorithm>
#include <cmath>

#include "metrics/stats.hpp"

namespace cnc::metrics {

namespace {

// When a move's motion ends: per axis its last rising edge plus the period that edge closes (the interval to the
// edge before it; with one edge, the commanded period), the latest over the axes. A constant-rate run of n edges
// then lasts exactly n periods from its first edge.
std::optional<TimePs> motion_end_ps(const MoveSpec& move, const EdgeIndex& idx, std::size_t m) {
    std::optional<TimePs> end;
    for (std::size_t a = 0; a < idx.axes.size(); ++a) {
        const EdgeRange r = idx.by_move[a][m];
        if (r.empty()) continue;
        const std::vector<TimePs>& rising = idx.axes[a].rising;
        const TimePs last = rising[r.end - 1];
        TimePs period = 0;
        if (r.size() >= 2) {
            period = last - rising[r.end - 2];
        } else if (a < move.rate_steps_per_s.size() && move.rate_steps_per_s[a] > 0.0) {
            period = s_to_ps(1.0 / move.rate_steps_per_s[a]);
        }
        end = std::max(end.value_or(last + period), last + period);
    }
    return end;
}

// Motion time of move m: from its first rising edge to the end of its motion, but never past the next move's
// first edge nor the job's end, so that the motion of the moves never overlaps and never exceeds the job.
std::optional<double> motion_time_s(const RunInput& in, const EdgeIndex& idx, std::size_t m) {
    if (!idx.move_first_edge_ps[m]) return std::nullopt;
    TimePs end = motion_end_ps(in.moves[m], idx, m).value_or(*idx.move_first_edge_ps[m]);
    for (std::size_t next = m + 1; next < in.moves.size(); ++next) {
        if (!idx.move_first_edge_ps[next]) continue;
        end = std::min(end, *idx.move_first_edge_ps[next]);
        break;
    }
    // A job that ended before this move's last edge (an aborted run, whose metrics are partial, or an analyzed
    // trace with no job window) does not cut it.
    if (in.t_job_end_ps > *idx.move_last_edge_ps[m]) end = std::min(end, in.t_job_end_ps);
    return ps_to_s(end - *idx.move_first_edge_ps[m]);
}

}  // namespace

TimingResult compute_timing(const RunInput& in, const EdgeIndex& idx) {
    TimingResult out;
    out.job_time_s = ps_to_s(in.t_job_end_ps - in.t_job_start_ps);
    out.moves.resize(in.moves.size());

    double feed_sum = 0.0;
    double feed_abs_sum = 0.0;
    for (std::size_t m = 0; m < in.moves.size(); ++m) {
        const MoveSpec& move = in.moves[m];
        MoveTiming& mt = out.moves[m];
        mt.motion_time_s = motion_time_s(in, idx, m);
        if (!mt.motion_time_s) continue;
        out.motion_time_s = out.motion_time_s.value_or(0.0) + *mt.motion_time_s;
        if (move.rapid || move.feed_mm_per_min <= 0.0 || *mt.motion_time_s <= 0.0) continue;
        mt.achieved_feed_mm_per_min = geom::distance(move.from_mm, move.to_mm) / *mt.motion_time_s * 60.0;
        mt.feed_error_pct = (*mt.achieved_feed_mm_per_min - move.feed_mm_per_min) / move.feed_mm_per_min * 100.0;
        ++out.feed_moves;
        feed_sum += *mt.feed_error_pct;
        feed_abs_sum += std::fabs(*mt.feed_error_pct);
        keep_max(out.feed_error_max_abs_pct, std::fabs(*mt.feed_error_pct));
    }
    if (out.feed_moves > 0) {
        out.feed_error_mean_pct = feed_sum / static_cast<double>(out.feed_moves);
        out.feed_error_mean_abs_pct = feed_abs_sum / static_cast<double>(out.feed_moves);
    }

    std::optional<std::size_t> previous;
    TimePs dead_total_ps = 0;
    for (std::size_t m = 0; m < in.moves.size(); ++m) {
        if (!idx.move_first_edge_ps[m]) continue;
        if (previous) {
            const TimePs dead = *idx.move_first_edge_ps[m] - *idx.move_last_edge_ps[*previous];
            out.gaps.push_back({*previous, m, dead});
            dead_total_ps += dead;
            keep_max(out.dead_max_ms, ps_to_s(dead) * 1e3);
        }
        previous = m;
    }
    if (!out.gaps.empty()) {
        out.dead_total_ms = ps_to_s(dead_total_ps) * 1e3;
        out.dead_mean_ms = *out.dead_total_ms / static_cast<double>(out.gaps.size());
    }

    std::optional<TimePs> first_edge;
    std::optional<TimePs> last_edge;
    for (const AxisEdges& a : idx.axes) {
        if (a.rising.empty()) continue;
        first_edge = first_edge ? std::min(*first_edge, a.rising.front()) : a.rising.front();
        last_edge = last_edge ? std::max(*last_edge, a.rising.back()) : a.rising.back();
    }
    if (first_edge) {
        out.lead_in_ms = ps_to_s(*first_edge - in.t_job_start_ps) * 1e3;
        out.tail_ms = ps_to_s(in.t_job_end_ps - *last_edge) * 1e3;
    }
    return out;
}

}  // namespace cnc::metrics
