#include "metrics/streaming/metrics_stream.hpp"

#include <algorithm>
#include <limits>
#include <utility>

#include "metrics/path/path_accuracy.hpp"
#include "metrics/pulse/edge_index.hpp"
#include "metrics/timing/programmed_moves.hpp"

namespace cnc::metrics {

namespace {

constexpr TimePs kEndOfTime = std::numeric_limits<TimePs>::max();

bool starts_after(TimePs t_ps, const RateSegment& s) {
    return t_ps < s.t_ps;
}

}  // namespace

MetricsStream::MetricsStream(RunInput shape, bool detail, PieceMeasured on_piece)
    : m_in(std::move(shape)), m_detail(detail), m_on_piece(std::move(on_piece)), m_laser(m_in.t_job_start_ps) {
    for (std::size_t a = 0; a < m_in.axes.size(); ++a) {
        const AxisTrace& trace = m_in.axes[a];
        AxisMetrics am;
        am.name = axis_label(m_in, a);
        am.step_signal = trace.step.name;
        am.dir_signal = trace.dir.name;
        m_axes.push_back(std::move(am));
        m_driver.emplace_back(m_in.limits, trace.step.initial, trace.dir.initial);
    }
    m_rising_done.assign(m_in.axes.size(), 0);
    m_pulse.resize(m_in.axes.size());
    m_out.moves = MoveRecords::spilled(m_in.axes.size());
}

void MetricsStream::fold(TimePs now_ps) {
    if (!m_in.moves.empty()) measure(now_ps, false);
}

// Measures the programmed moves that can no longer change (all of them when `final`) and drops their inputs. A move
// is final once a later programmed move has its first edge (its motion time is cut there, and its pieces are
// followed by a piece that has begun) and all its pieces have ended.
void MetricsStream::measure(TimePs now_ps, bool final) {
    // Until the pieces past the kept neighbour hold two programmed moves, none can be final: the batch code need
    // not run over a window that only grows (a long move spans many slices).
    if (!final && !two_moves_pending()) return;
    if (m_in.commanded) {
        m_in.commanded->count_before_steps.clear();
        for (const AxisMetrics& am : m_axes) m_in.commanded->count_before_steps.push_back(am.net_steps);
    }
    for (const std::vector<RateSegment>& segments : m_in.rate_segments) m_rate_segmented |= !segments.empty();
    // Nor while a STEP before the earliest cut lies in an axis's last known rate segment: its run cannot be whole
    // yet (cut_allowed), and the batch code over a window that only grows would run again each slice (under load the
    // slices shrink, and a run whose work per slice grows with the window crawls).
    if (!final && step_in_open_segment(earliest_cut_ps())) return;
    const RunMetrics r = compute_metrics(m_in);
    const std::size_t first_group = m_has_prev ? 1 : 0;
    std::vector<std::size_t> group_piece{0};  // [group] its first piece in m_in.moves
    r.moves.for_each([&group_piece](const MoveMetrics& mm) { group_piece.push_back(group_piece.back() + mm.pieces); });
    std::size_t end_group = r.moves.size();
    if (!final) {
        std::size_t last_with_edge = first_group;
        for (std::size_t g = first_group; g < r.moves.size(); ++g) {
            if (r.moves[g].t_first_edge_ps) last_with_edge = g;
        }
        end_group = last_with_edge;
        for (std::size_t g = first_group; g < end_group; ++g) {
            for (std::size_t p = group_piece[g]; p < group_piece[g + 1]; ++p) {
                if (m_in.moves[p].t_end_ps >= now_ps) end_group = std::min(end_group, g);
            }
        }
        while (end_group > first_group && !cut_allowed(r, m_in.moves[group_piece[end_group]].t_begin_ps, now_ps)) {
            --end_group;
        }
        if (end_group <= first_group) return;
    }
    const std::size_t first_piece = group_piece[first_group];
    const std::size_t cut_piece = group_piece[end_group];
    const TimePs cut_ps = final ? kEndOfTime : m_in.moves[cut_piece].t_begin_ps;
    const bool first_fold = m_pieces_done == 0;
    if (first_fold) count_unattributed_unmatched(r);

    for (std::size_t p = first_piece; p < cut_piece; ++p) {
        const MoveMetrics& piece = r.pieces[p];
        if (m_in.moves[p].rapid && piece.t_first_edge_ps) {
            append_merged(m_rapid, {*piece.t_first_edge_ps, *piece.t_last_edge_ps});
        }
        for (std::size_t a = 0; a < m_axes.size(); ++a) {
            keep_max(m_axes[a].sync_max_abs_ns, piece.sync_max_abs_ns[a]);
            keep_max(m_out.pulse.sync_max_abs_ns, piece.sync_max_abs_ns[a]);
            if (a < piece.sync_unmatched_edges.size() && m_axes[a].sync_unmatched_edges) {
                *m_axes[a].sync_unmatched_edges += piece.sync_unmatched_edges[a];
            }
        }
        keep_max(m_out.path.endpoint_vs_command_max_um, piece.path.endpoint_vs_command_um);
        keep_max(m_out.path.endpoint_vs_program_max_um, piece.path.endpoint_vs_program_um);
        if (m_on_piece) m_on_piece(piece);
        if (m_detail) m_out.pieces.push_back(piece);
    }
    for (std::size_t g = first_group; g < end_group; ++g) {
        MoveMetrics mm = r.moves[g];
        m_timing.add(m_moves_done++, mm.timing, mm.t_first_edge_ps, mm.t_last_edge_ps);
        m_worst.add(mm);
        m_out.moves.append(mm);
    }
    for (std::size_t a = 0; a < m_axes.size(); ++a) {
        for (PulseRun run : r.axes[a].runs) {
            // A rate segment's run before the first piece belongs to none (first window only).
            if (run.move ? *run.move < first_piece || *run.move >= cut_piece
                         : !first_fold || run.t_first_ps >= cut_ps) {
                continue;
            }
            if (run.move) run.move = m_pieces_done + (*run.move - first_piece);
            run.edges_range.begin += m_rising_done[a];
            run.edges_range.end += m_rising_done[a];
            m_pulse[a].add(run);
            if (m_detail) m_axes[a].runs.push_back(run);
        }
    }

    const EdgeIndex idx = index_edges(m_in);
    const MoveTimeline timeline(m_in.moves);
    const std::size_t first_sample = m_sample_measured ? 1 : 0;
    std::size_t end_sample = first_sample;
    for (; end_sample < m_in.tool.size() && m_in.tool[end_sample].t_ps < cut_ps; ++end_sample) {
        const SampleError e = sample_error(m_in, idx, timeline, end_sample);
        m_contour.add(e.contour_um);
        m_following.add(e.following_um);
        m_slow.add(m_in.tool[end_sample], m_in.moves[e.move].feed_mm_per_min);
        ++m_out.path.samples;
        m_last_sample_ps = m_in.tool[end_sample].t_ps;
    }
    fold_exposure(first_sample, end_sample);
    if (final) m_out.path.job_end_um = r.path.job_end_um;

    take_edges_before(cut_ps, first_fold, r);
    m_pieces_done += cut_piece - first_piece;
    if (final) return;
    drop_before(cut_ps, cut_piece);
    drop_rate_segments(r, cut_ps);
    // The slow stretches are known up to the last sample measured, which is before the cut (the one after it may
    // still join or split them); without samples so far nothing is folded (with none at all, the dwell is not
    // measured).
    if (m_in.laser && m_last_sample_ps) fold_laser(*m_last_sample_ps);
}

bool MetricsStream::cut_allowed(const RunMetrics& r, TimePs cut_ps, TimePs now_ps) const {
    // The crossings that may match an edge before the cut lie where the commanded trajectory is already known.
    if (m_in.commanded) {
        const CommandedTrajectory& c = *m_in.commanded;
        if (cut_ps > c.t_end_ps - c.sync_window_ps - c.scan_step_ps) return false;
    }
    // A rate segment's run is measured whole, with the piece its first edge is in: every segment with an edge
    // before the cut must have ended (the next one known and begun), so that all its edges are here.
    for (std::size_t a = 0; a < m_in.rate_segments.size() && a < r.axes.size(); ++a) {
        const std::vector<RateSegment>& segments = m_in.rate_segments[a];
        if (segments.empty()) continue;
        for (const PulseRun& run : r.axes[a].runs) {
            if (run.t_first_ps >= cut_ps) break;
            const auto next = std::upper_bound(segments.begin(), segments.end(), run.t_first_ps, starts_after);
            if (next == segments.end() || next->t_ps > now_ps) return false;
        }
    }
    return true;
}

void MetricsStream::count_unattributed_unmatched(const RunMetrics& r) {
    for (std::size_t a = 0; a < m_axes.size(); ++a) {
        if (!r.axes[a].sync_unmatched_edges) continue;
        std::size_t in_pieces = 0;
        for (const MoveMetrics& piece : r.pieces) {
            if (a < piece.sync_unmatched_edges.size()) in_pieces += piece.sync_unmatched_edges[a];
        }
        m_axes[a].sync_unmatched_edges = *r.axes[a].sync_unmatched_edges - in_pieces;
    }
}

void MetricsStream::fold_laser(TimePs horizon_ps) {
    m_laser.fold(m_in.laser->take_before(horizon_ps), m_rapid, &m_slow.so_far(), horizon_ps);
    const auto open = std::find_if(m_rapid.begin(), m_rapid.end(),
                                   [horizon_ps](const TimeInterval& iv) { return iv.end > horizon_ps; });
    m_rapid.erase(m_rapid.begin(), open);
    m_slow.drop_ending_by(horizon_ps);
}

void MetricsStream::fold_exposure(std::size_t first_sample, std::size_t end_sample) {
    if (!m_in.laser) return;
    const auto begin = m_in.tool.begin();
    m_exposure.fold(begin + static_cast<std::ptrdiff_t>(first_sample), begin + static_cast<std::ptrdiff_t>(end_sample),
                    *m_in.laser);
}

void MetricsStream::drop_rate_segments(const RunMetrics& r, TimePs cut_ps) {
    for (std::size_t a = 0; a < m_in.rate_segments.size() && a < r.axes.size(); ++a) {
        std::vector<RateSegment>& segments = m_in.rate_segments[a];
        // The segment that governs the cut stays, unless its run began before the cut and was measured whole (its
        // edges after the cut, still in pending(), are then in no run of the next window).
        auto keep = std::upper_bound(segments.begin(), segments.end(), cut_ps, starts_after);
        if (keep != segments.begin()) --keep;
        for (const PulseRun& run : r.axes[a].runs) {
            if (run.t_first_ps >= cut_ps) break;
            keep = std::max(keep, std::upper_bound(segments.begin(), segments.end(), run.t_first_ps, starts_after));
        }
        segments.erase(segments.begin(), keep);
    }
}

TimePs MetricsStream::earliest_cut_ps() const {
    for (std::size_t p = (m_has_prev ? 1 : 0) + 1; p < m_in.moves.size(); ++p) {
        if (!same_programmed_move(m_in.moves[p - 1], m_in.moves[p])) return m_in.moves[p].t_begin_ps;
    }
    return kEndOfTime;
}

bool MetricsStream::step_in_open_segment(TimePs before_ps) const {
    for (std::size_t a = 0; a < m_in.rate_segments.size() && a < m_in.axes.size(); ++a) {
        const std::vector<RateSegment>& segments = m_in.rate_segments[a];
        if (segments.empty()) continue;
        const std::vector<Edge>& edges = m_in.axes[a].step.edges;
        auto e = std::lower_bound(edges.begin(), edges.end(), segments.back().t_ps,
                                  [](const Edge& edge, TimePs t) { return edge.t_ps < t; });
        for (; e != edges.end() && e->t_ps < before_ps; ++e) {
            if (e->level) return true;
        }
    }
    return false;
}

bool MetricsStream::two_moves_pending() const {
    for (std::size_t p = (m_has_prev ? 1 : 0) + 1; p < m_in.moves.size(); ++p) {
        if (!same_programmed_move(m_in.moves[p - 1], m_in.moves[p])) return true;
    }
    return false;
}

void MetricsStream::take_edges_before(TimePs cut_ps, bool first_fold, const RunMetrics& r) {
    for (std::size_t a = 0; a < m_axes.size(); ++a) {
        AxisTrace& trace = m_in.axes[a];
        const AxisTrace window{trace.name, trace.step.take_before(cut_ps), trace.dir.take_before(cut_ps),
                               trace.steps_per_mm, trace.dir_high_is_positive};
        const AxisEdges edges = extract_edges(window);
        AxisMetrics& am = m_axes[a];
        am.rising_edges += edges.rising.size();
        am.falling_edges += edges.falling;
        am.dir_changes += edges.dir_changes.size();
        for (const int s : edges.rising_sign) am.net_steps += s;
        if (first_fold) am.unattributed_edges = r.axes[a].unattributed_edges;
        if (!edges.rising.empty()) {
            m_first_edge_ps = std::min(m_first_edge_ps.value_or(edges.rising.front()), edges.rising.front());
            m_last_edge_ps = std::max(m_last_edge_ps.value_or(edges.rising.back()), edges.rising.back());
        }
        m_rising_done[a] += edges.rising.size();
        m_driver[a].add(window.step.edges, window.dir.edges);
    }
}

void MetricsStream::drop_before(TimePs cut_ps, std::size_t cut_piece) {
    // The last sample before the cut stays: the next window's first piece may end before its own first sample.
    const auto after = std::lower_bound(m_in.tool.begin(), m_in.tool.end(), cut_ps,
                                        [](const ToolSample& s, TimePs t) { return s.t_ps < t; });
    if (after != m_in.tool.begin()) {
        m_in.tool.erase(m_in.tool.begin(), std::prev(after));
        m_sample_measured = true;
    }
    m_in.moves.erase(m_in.moves.begin(), m_in.moves.begin() + static_cast<std::ptrdiff_t>(cut_piece - 1));

    m_has_prev = true;
}

RunMetrics MetricsStream::finish(TimePs t_job_end_ps) {
    m_in.t_job_end_ps = t_job_end_ps;
    if (m_in.moves.empty()) {  // nothing was measured or dropped
        fold_exposure(0, m_in.tool.size());
        return compute_metrics(m_in);
    }
    measure(kEndOfTime, true);

    RunMetrics out = std::move(m_out);
    out.with_moves = true;
    out.runs_per_rate_segment = m_rate_segmented;
    out.with_tool = out.path.samples > 0;
    out.limits = m_in.limits;
    out.run_split_tolerance = m_in.run_split_tolerance;
    for (std::size_t a = 0; a < m_axes.size(); ++a) {
        AxisMetrics& am = m_axes[a];
        am.driver = m_driver[a].report();
        finish_axis(am, m_in.axes[a].steps_per_mm, m_pulse[a].summary());
        add_axis_totals(out.pulse, am);
        out.axes.push_back(std::move(am));
    }
    out.worst = m_worst.lists();
    out.path.contour_max_um = m_contour.max_abs();
    out.path.contour_rms_um = m_contour.rms();
    out.path.following_max_um = m_following.max_abs();
    out.path.following_rms_um = m_following.rms();
    out.timing = m_timing.finish(m_in.t_job_start_ps, t_job_end_ps, m_first_edge_ps, m_last_edge_ps);
    if (m_in.laser) {
        std::optional<std::vector<TimeInterval>> slow;
        if (out.with_tool) slow = m_slow.finish();
        out.laser = m_laser.finish(*m_in.laser, t_job_end_ps, m_rapid, slow);
    }
    return out;
}

}  // namespace cnc::metrics
