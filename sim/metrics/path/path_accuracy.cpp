#include "metrics/path/path_accuracy.hpp"

#include <algorithm>
#include <stdexcept>

#include "metrics/commanded.hpp"
#include "metrics/stats.hpp"
#include "metrics/timing/programmed_moves.hpp"

namespace cnc::metrics {

namespace {

constexpr double kUmPerMm = 1000.0;

geom::Vec2 expected_position(const MoveSpec& m, TimePs t0_ps, TimePs t_ps) {
    const double length_mm = geom::distance(m.from_mm, m.to_mm);
    if (length_mm <= 0.0) return m.from_mm;
    const double speed_mm_per_s = m.feed_mm_per_min / 60.0;
    const double s_mm = std::clamp(speed_mm_per_s * ps_to_s(t_ps - t0_ps), 0.0, length_mm);
    return m.from_mm + (m.to_mm - m.from_mm) * (s_mm / length_mm);
}

double contour_distance_mm(const std::vector<MoveSpec>& moves, std::size_t active, geom::Vec2 p) {
    double d = moves[active].path.distance_to(p);
    if (active > 0) d = std::min(d, moves[active - 1].path.distance_to(p));
    if (active + 1 < moves.size()) d = std::min(d, moves[active + 1].path.distance_to(p));
    return d;
}

}  // namespace

SampleError sample_error(const RunInput& in, const EdgeIndex& idx, const MoveTimeline& timeline, std::size_t i) {
    const std::vector<MoveSpec>& moves = in.moves;
    const ToolSample& s = in.tool[i];
    SampleError e;
    e.move = timeline.active_at(s.t_ps).value_or(0);
    e.contour_um = contour_distance_mm(moves, e.move, s.pos) * kUmPerMm;
    if (in.commanded) {
        const geom::Vec2 cmd = commanded_at(*in.commanded, s.t_ps).pos_mm;
        e.following_um = geom::distance(s.pos, cmd) * kUmPerMm;
        if (i > 0) e.following_um = std::max(e.following_um, geom::distance(in.tool[i - 1].pos, cmd) * kUmPerMm);
    } else {
        const TimePs t0 = idx.move_first_edge_ps[e.move].value_or(moves[e.move].t_begin_ps);
        e.following_um = geom::distance(s.pos, expected_position(moves[e.move], t0, s.t_ps)) * kUmPerMm;
    }
    return e;
}

PathResult compute_path_accuracy(const RunInput& in, const EdgeIndex& idx) {
    PathResult out;
    const std::vector<MoveSpec>& moves = in.moves;
    out.moves.resize(moves.size());
    if (moves.empty() || in.tool.empty()) return out;
    const bool sorted = std::is_sorted(in.tool.begin(), in.tool.end(),
                                       [](const ToolSample& a, const ToolSample& b) { return a.t_ps < b.t_ps; });
    if (!sorted) throw std::invalid_argument("tool samples are not in time order");

    const MoveTimeline timeline(moves);
    std::vector<MaxRms> contour(moves.size());
    std::vector<MaxRms> following(moves.size());
    MaxRms contour_all;
    MaxRms following_all;
    for (std::size_t i = 0; i < in.tool.size(); ++i) {
        const SampleError e = sample_error(in, idx, timeline, i);
        contour[e.move].add(e.contour_um);
        following[e.move].add(e.following_um);
        contour_all.add(e.contour_um);
        following_all.add(e.following_um);
    }
    out.samples = in.tool.size();
    out.contour_max_um = contour_all.max_abs();
    out.contour_rms_um = contour_all.rms();
    out.following_max_um = following_all.max_abs();
    out.following_rms_um = following_all.rms();

    for (std::size_t m = 0; m < moves.size(); ++m) {
        MovePath& mp = out.moves[m];
        mp.samples = contour[m].count();
        mp.contour_max_um = contour[m].max_abs();
        mp.following_max_um = following[m].max_abs();
        mp.following_rms_um = following[m].rms();
        const auto after_end = std::upper_bound(in.tool.begin(), in.tool.end(), moves[m].t_end_ps,
                                                [](TimePs t, const ToolSample& s) { return t < s.t_ps; });
        if (after_end == in.tool.begin()) continue;
        const geom::Vec2 at_end = std::prev(after_end)->pos;
        mp.endpoint_vs_command_um = geom::distance(at_end, moves[m].to_mm) * kUmPerMm;
        keep_max(out.endpoint_vs_command_max_um, mp.endpoint_vs_command_um);
        const bool segment_ends = m + 1 == moves.size() || !same_programmed_move(moves[m], moves[m + 1]);
        if (segment_ends) {
            mp.endpoint_vs_program_um = geom::distance(at_end, moves[m].path.end) * kUmPerMm;
            keep_max(out.endpoint_vs_program_max_um, mp.endpoint_vs_program_um);
        }
    }
    out.job_end_um = geom::distance(in.tool.back().pos, moves.back().path.end) * kUmPerMm;
    return out;
}

}  // namespace cnc::metrics
