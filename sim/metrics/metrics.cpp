#include "metrics/metrics.hpp"

#include <cmath>
#include <utility>

#include "metrics/pulse/edge_index.hpp"
#include "metrics/pulse/sync_error.hpp"
#include "metrics/stats.hpp"
#include "metrics/timing/programmed_moves.hpp"

namespace cnc::metrics {

namespace {

AxisMetrics axis_metrics(const RunInput& in, const EdgeIndex& idx, std::size_t a) {
    const AxisTrace& trace = in.axes[a];
    const AxisEdges& edges = idx.axes[a];
    AxisMetrics am;
    am.name = axis_label(in, a);
    am.step_signal = trace.step.name;
    am.dir_signal = trace.dir.name;
    am.rising_edges = edges.rising.size();
    am.falling_edges = edges.falling;
    am.dir_changes = edges.dir_changes.size();
    for (const int s : edges.rising_sign) am.net_steps += s;
    am.unattributed_edges = idx.unattributed[a];
    am.runs = axis_runs(in, idx, a);
    am.driver = check_driver_timing(trace.step, trace.dir, in.limits);
    finish_axis(am, trace.steps_per_mm, summarise_runs(am.runs));
    return am;
}

MoveMetrics piece_metrics(const RunInput& in, const EdgeIndex& idx, std::size_t m) {
    const MoveSpec& spec = in.moves[m];
    MoveMetrics mm;
    mm.index = spec.index;
    mm.line = spec.line;
    mm.feed_mm_per_min = spec.feed_mm_per_min;
    mm.programmed = programmed_end(spec);
    mm.t_first_edge_ps = idx.move_first_edge_ps[m];
    mm.t_last_edge_ps = idx.move_last_edge_ps[m];
    for (std::size_t a = 0; a < idx.axes.size(); ++a) {
        mm.steps_commanded.push_back(a < spec.steps.size() ? spec.steps[a] : 0);
        std::int64_t emitted = 0;
        const EdgeRange r = idx.by_move[a][m];
        for (std::size_t k = r.begin; k < r.end; ++k) emitted += idx.axes[a].rising_sign[k];
        mm.steps_emitted.push_back(emitted);
    }
    return mm;
}

// Following RMS over the samples of several pieces, from each piece's RMS and count.
void add_rms(std::optional<double>& rms, std::size_t& count, const MovePath& piece) {
    if (!piece.following_rms_um || piece.samples == 0) return;
    const double sum_sq = rms ? *rms * *rms * static_cast<double>(count) : 0.0;
    const double piece_sq = *piece.following_rms_um * *piece.following_rms_um * static_cast<double>(piece.samples);
    count += piece.samples;
    rms = std::sqrt((sum_sq + piece_sq) / static_cast<double>(count));
}

MoveMetrics programmed_metrics(const RunInput& in, const std::vector<MoveMetrics>& pieces, const ProgrammedMove& pm) {
    const MoveSpec& spec = in.moves[pm.first_piece];
    MoveMetrics mm = pieces[pm.first_piece];
    mm.index = spec.programmed >= 0 ? spec.programmed + 1 : spec.index;
    mm.pieces = pm.end_piece - pm.first_piece;
    mm.t_first_edge_ps = pm.t_first_edge_ps;
    mm.t_last_edge_ps = pm.t_last_edge_ps;
    std::size_t rms_count = mm.path.following_rms_um ? mm.path.samples : 0;
    for (std::size_t p = pm.first_piece + 1; p < pm.end_piece; ++p) {
        const MoveMetrics& piece = pieces[p];
        for (std::size_t a = 0; a < mm.steps_commanded.size(); ++a) {
            mm.steps_commanded[a] += piece.steps_commanded[a];
            mm.steps_emitted[a] += piece.steps_emitted[a];
            keep_max(mm.sync_max_abs_ns[a], piece.sync_max_abs_ns[a]);
            if (a < mm.sync_unmatched_edges.size()) mm.sync_unmatched_edges[a] += piece.sync_unmatched_edges[a];
        }
        MovePath& path = mm.path;
        add_rms(path.following_rms_um, rms_count, piece.path);
        path.samples += piece.path.samples;
        keep_max(path.contour_max_um, piece.path.contour_max_um);
        keep_max(path.following_max_um, piece.path.following_max_um);
        keep_max(path.endpoint_vs_command_um, piece.path.endpoint_vs_command_um);
        path.endpoint_vs_program_um = piece.path.endpoint_vs_program_um;
    }
    return mm;
}

}  // namespace

ProgrammedEnd programmed_end(const MoveSpec& spec) {
    ProgrammedEnd e;
    const geom::Segment& path = spec.path;
    e.kind = spec.rapid             ? ProgrammedKind::Rapid
             : !path.is_arc         ? ProgrammedKind::Line
             : path.sweep_rad < 0.0 ? ProgrammedKind::ArcCw
                                    : ProgrammedKind::ArcCcw;
    e.x_mm = path.end.x_mm;
    e.y_mm = path.end.y_mm;
    e.z_mm = spec.z_end_mm;
    if (path.is_arc) {
        e.center_x_mm = path.center.x_mm;
        e.center_y_mm = path.center.y_mm;
    }
    return e;
}

const char* to_string(ProgrammedKind kind) {
    switch (kind) {
        case ProgrammedKind::Rapid:
            return "rapid";
        case ProgrammedKind::Line:
            return "line";
        case ProgrammedKind::ArcCw:
            return "arc_cw";
        case ProgrammedKind::ArcCcw:
            return "arc_ccw";
    }
    return "?";
}

void finish_axis(AxisMetrics& am, double steps_per_mm, const AxisPulseSummary& pulse) {
    if (steps_per_mm > 0.0) {
        am.travel_mm = static_cast<double>(am.rising_edges) / steps_per_mm;
        am.net_mm = static_cast<double>(am.net_steps) / steps_per_mm;
    }
    am.pulse = pulse;
}

void add_axis_totals(PulseTotals& t, const AxisMetrics& am) {
    keep_max(t.jitter_std_max_ns, am.pulse.jitter_std_max_ns);
    keep_max(t.jitter_pp_max_ns, am.pulse.jitter_pp_max_ns);
    keep_max(t.tie_rms_max_ns, am.pulse.tie_rms_max_ns);
    keep_max(t.tie_max_ns, am.pulse.tie_max_ns);
    keep_max(t.tie_max_period_frac, am.pulse.tie_max_period_frac);
    keep_worst_signed(t.rate_error_worst_pct, am.pulse.rate_error_worst_pct);
    t.driver_violations += am.driver.total_violations();
}

RunMetrics compute_metrics(const RunInput& in) {
    const EdgeIndex idx = index_edges(in);
    RunMetrics out;
    out.with_moves = !in.moves.empty();
    out.with_tool = !in.tool.empty();
    for (const std::vector<RateSegment>& segments : in.rate_segments) {
        out.runs_per_rate_segment = out.runs_per_rate_segment || !segments.empty();
    }
    out.limits = in.limits;
    out.run_split_tolerance = in.run_split_tolerance;

    const SyncResult sync = compute_sync(in, idx);
    for (std::size_t a = 0; a < in.axes.size(); ++a) {
        AxisMetrics am = axis_metrics(in, idx, a);
        am.sync_max_abs_ns = sync.axis_max_abs_ns[a];
        if (a < sync.axis_unmatched_edges.size()) am.sync_unmatched_edges = sync.axis_unmatched_edges[a];
        add_axis_totals(out.pulse, am);
        out.axes.push_back(std::move(am));
    }
    out.pulse.sync_max_abs_ns = sync.max_abs_ns;

    const std::vector<ProgrammedMove> programmed = programmed_moves(in, idx);
    out.path = compute_path_accuracy(in, idx);
    out.timing = compute_timing(in, idx, programmed);
    out.laser = compute_laser(in, idx);
    // Per-move records are most of a long job's metrics: sized once instead of grown by doubling.
    out.pieces.reserve(in.moves.size());
    std::vector<MoveMetrics> moves;
    moves.reserve(programmed.size());
    for (std::size_t m = 0; m < in.moves.size(); ++m) {
        MoveMetrics mm = piece_metrics(in, idx, m);
        mm.sync_max_abs_ns = sync.move_axis_max_abs_ns[m];
        if (in.commanded) mm.sync_unmatched_edges = sync.move_axis_unmatched_edges[m];
        mm.path = std::move(out.path.moves[m]);
        out.pieces.push_back(std::move(mm));
    }
    for (std::size_t m = 0; m < programmed.size(); ++m) {
        MoveMetrics mm = programmed_metrics(in, out.pieces, programmed[m]);
        mm.timing = std::move(out.timing.moves[m]);
        moves.push_back(std::move(mm));
    }
    out.worst = worst_moves(moves);
    out.moves = MoveRecords(std::move(moves));
    out.timing.moves.clear();
    out.path.moves.clear();
    return out;
}

}  // namespace cnc::metrics
