#include "metrics/timing/move_timing.hpp"

#include <algorithm>
#include <cmath>

#include "metrics/stats.hpp"
#include "metrics/timing/cruise_feed.hpp"

namespace cnc::metrics {

namespace {

constexpr double kSecondsPerMinute = 60.0;

// The piece of programmed move pm that holds rising edge k of axis a.
const MoveSpec& piece_of(const RunInput& in, const EdgeIndex& idx, const ProgrammedMove& pm, std::size_t a,
                         std::size_t k) {
    for (std::size_t p = pm.first_piece; p + 1 < pm.end_piece; ++p) {
        if (k < idx.by_move[a][p].end) return in.moves[p];
    }
    return in.moves[pm.end_piece - 1];
}

// When a programmed move's motion ends: per axis its last rising edge plus the period that edge closes (the
// interval to the edge before it; with one edge, its piece's commanded period), the latest over the axes. A
// constant-rate run of n edges then lasts exactly n periods from its first edge.
std::optional<TimePs> motion_end_ps(const RunInput& in, const EdgeIndex& idx, const ProgrammedMove& pm) {
    std::optional<TimePs> end;
    for (std::size_t a = 0; a < idx.axes.size(); ++a) {
        const EdgeRange r = pm.edges[a];
        if (r.empty()) continue;
        const std::vector<TimePs>& rising = idx.axes[a].rising;
        const TimePs last = rising[r.end - 1];
        TimePs period = 0;
        if (r.size() >= 2) {
            period = last - rising[r.end - 2];
        } else {
            const MoveSpec& piece = piece_of(in, idx, pm, a, r.begin);
            if (a < piece.rate_steps_per_s.size() && piece.rate_steps_per_s[a] > 0.0) {
                period = s_to_ps(1.0 / piece.rate_steps_per_s[a]);
            }
        }
        end = std::max(end.value_or(last + period), last + period);
    }
    return end;
}

// Motion time of programmed move m: from its first rising edge to the end of its motion, but never past the next
// move's first edge nor the job's end, so that the motion of the moves never overlaps and never exceeds the job.
std::optional<double> motion_time_s(const RunInput& in, const EdgeIndex& idx,
                                    const std::vector<ProgrammedMove>& programmed, std::size_t m) {
    const ProgrammedMove& pm = programmed[m];
    if (!pm.t_first_edge_ps) return std::nullopt;
    TimePs end = motion_end_ps(in, idx, pm).value_or(*pm.t_first_edge_ps);
    for (std::size_t next = m + 1; next < programmed.size(); ++next) {
        if (!programmed[next].t_first_edge_ps) continue;
        end = std::min(end, *programmed[next].t_first_edge_ps);
        break;
    }
    // A job that ended before this move's last edge (an aborted run, whose metrics are partial, or an analyzed
    // trace with no job window) does not cut it.
    if (in.t_job_end_ps > *pm.t_last_edge_ps) end = std::min(end, in.t_job_end_ps);
    return ps_to_s(end - *pm.t_first_edge_ps);
}

// The gaps between the pieces of programmed move pm that step: from the last rising edge of one to the first of the
// next (a piece with no edge is passed over).
void inside_gaps(const EdgeIndex& idx, const ProgrammedMove& pm, MoveTiming& mt) {
    std::optional<TimePs> last_ps;
    for (std::size_t p = pm.first_piece; p < pm.end_piece; ++p) {
        const std::optional<TimePs> first_ps = idx.move_first_edge_ps[p];
        if (!first_ps) continue;
        if (last_ps) {
            const TimePs dead = *first_ps - *last_ps;
            ++mt.inside_gaps;
            mt.dead_inside_ps += dead;
            mt.dead_inside_max_ps = std::max(mt.dead_inside_max_ps, dead);
        }
        last_ps = idx.move_last_edge_ps[p];
    }
}

// The achieved feed of a cutting move run by a planner: the STEP edges' path speed over its cruise (none: the
// commanded speed never reached F, or the cruise holds fewer than two edge instants).
std::optional<double> cruise_feed_mm_per_min(const RunInput& in, const ProgrammedMove& pm, StepPosition& position,
                                             bool& below_feed) {
    const MoveSpec& first = in.moves[pm.first_piece];
    const auto cruise = cruise_window(*in.commanded, first.t_begin_ps, in.moves[pm.end_piece - 1].t_end_ps,
                                      first.feed_mm_per_min / kSecondsPerMinute);
    below_feed = !cruise;
    if (!cruise) return std::nullopt;
    const auto travel = position.travel(first.path, cruise->first, cruise->second);
    if (!travel) return std::nullopt;
    return travel->path_mm / ps_to_s(travel->t_last_ps - travel->t_first_ps) * kSecondsPerMinute;
}

}  // namespace

void TimingFold::add(std::size_t move, MoveTiming& mt, std::optional<TimePs> t_first_edge_ps,
                     std::optional<TimePs> t_last_edge_ps) {
    if (mt.motion_time_s) m_out.motion_time_s = m_out.motion_time_s.value_or(0.0) + *mt.motion_time_s;
    m_out.below_feed_moves += mt.below_feed ? 1 : 0;
    if (mt.feed_error_pct) {
        ++m_out.feed_moves;
        m_feed_sum += *mt.feed_error_pct;
        m_feed_abs_sum += std::fabs(*mt.feed_error_pct);
        keep_max(m_out.feed_error_max_abs_pct, std::fabs(*mt.feed_error_pct));
    }
    mt.dead_after_move.reset();
    mt.dead_before_ps.reset();
    if (!t_first_edge_ps) return;
    m_out.inside_gap_count += mt.inside_gaps;
    m_dead_inside_ps += mt.dead_inside_ps;
    m_dead_inside_max_ps = std::max(m_dead_inside_max_ps, mt.dead_inside_max_ps);
    if (m_previous) {
        const TimePs dead = *t_first_edge_ps - m_previous_last_edge_ps;
        mt.dead_after_move = *m_previous;
        mt.dead_before_ps = dead;
        ++m_out.gap_count;
        m_dead_total_ps += dead;
        keep_max(m_out.dead_max_ms, ps_to_s(dead) * 1e3);
    }
    m_previous = move;
    m_previous_last_edge_ps = *t_last_edge_ps;
}

TimingResult TimingFold::finish(TimePs t_job_start_ps, TimePs t_job_end_ps, std::optional<TimePs> first_edge_ps,
                                std::optional<TimePs> last_edge_ps) {
    TimingResult out = std::move(m_out);
    if (out.feed_moves > 0) {
        out.feed_error_mean_pct = m_feed_sum / static_cast<double>(out.feed_moves);
        out.feed_error_mean_abs_pct = m_feed_abs_sum / static_cast<double>(out.feed_moves);
    }
    if (out.gap_count > 0) {
        out.dead_total_ms = ps_to_s(m_dead_total_ps) * 1e3;
        out.dead_mean_ms = *out.dead_total_ms / static_cast<double>(out.gap_count);
    }
    if (m_previous) {
        out.dead_inside_total_ms = ps_to_s(m_dead_inside_ps) * 1e3;
        out.dead_all_total_ms = ps_to_s(m_dead_total_ps + m_dead_inside_ps) * 1e3;
    }
    if (out.inside_gap_count > 0) {
        out.dead_inside_mean_ms = *out.dead_inside_total_ms / static_cast<double>(out.inside_gap_count);
        out.dead_inside_max_ms = ps_to_s(m_dead_inside_max_ps) * 1e3;
    }
    // A controller that goes on stepping after its host stopped (an aborted run: its metrics are partial) keeps
    // the job open to its last edge, so that motion <= job and the tail >= 0 on every run.
    const TimePs job_end_ps = last_edge_ps ? std::max(t_job_end_ps, *last_edge_ps) : t_job_end_ps;
    out.job_time_s = ps_to_s(job_end_ps - t_job_start_ps);
    if (first_edge_ps) {
        out.lead_in_ms = ps_to_s(*first_edge_ps - t_job_start_ps) * 1e3;
        out.tail_ms = ps_to_s(job_end_ps - *last_edge_ps) * 1e3;
    }
    return out;
}

TimingResult compute_timing(const RunInput& in, const EdgeIndex& idx, const std::vector<ProgrammedMove>& programmed) {
    std::vector<MoveTiming> moves(programmed.size());
    StepPosition position(in, idx);
    TimingFold fold;
    for (std::size_t m = 0; m < programmed.size(); ++m) {
        const ProgrammedMove& pm = programmed[m];
        const MoveSpec& first = in.moves[pm.first_piece];
        MoveTiming& mt = moves[m];
        mt.motion_time_s = motion_time_s(in, idx, programmed, m);
        inside_gaps(idx, pm, mt);
        const bool cutting = mt.motion_time_s && !first.rapid && first.feed_mm_per_min > 0.0 && *mt.motion_time_s > 0.0;
        if (cutting) {
            if (in.commanded) {
                mt.achieved_feed_mm_per_min = cruise_feed_mm_per_min(in, pm, position, mt.below_feed);
            } else {
                mt.achieved_feed_mm_per_min = first.path.length_mm() / *mt.motion_time_s * kSecondsPerMinute;
            }
            if (mt.achieved_feed_mm_per_min) {
                mt.feed_error_pct =
                    (*mt.achieved_feed_mm_per_min - first.feed_mm_per_min) / first.feed_mm_per_min * 100.0;
            }
        }
        fold.add(m, mt, pm.t_first_edge_ps, pm.t_last_edge_ps);
    }

    std::optional<TimePs> first_edge;
    std::optional<TimePs> last_edge;
    for (const AxisEdges& a : idx.axes) {
        if (a.rising.empty()) continue;
        first_edge = first_edge ? std::min(*first_edge, a.rising.front()) : a.rising.front();
        last_edge = last_edge ? std::max(*last_edge, a.rising.back()) : a.rising.back();
    }
    TimingResult out = fold.finish(in.t_job_start_ps, in.t_job_end_ps, first_edge, last_edge);
    out.moves = std::move(moves);
    return out;
}

}  // namespace cnc::metrics
