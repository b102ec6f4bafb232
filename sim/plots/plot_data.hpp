// The data behind the plots of one run, written as gnuplot data files (whitespace columns, `#` header lines) and
// a meta.json that says which files exist. Everything is drawn from what a run already measured (the edge logs,
// tool samples, moves and metrics) and from what its architecture adds (ArchRun::gap_causes, ArchRun::series,
// ArchRun::plots), so a model that reports more gets more plots without touching the renderer.
#pragma once
#include <filesystem>
#include <string>

#include "metrics/metrics.hpp"
#include "run/arch_run.hpp"

namespace cnc::sim {

// Files in `dir` (created):
//   program.dat, rapids.dat   x_mm y_mm: the programmed feed moves and rapids, one block per connected piece
//   moves.dat                 move line kind end_x_mm end_y_mm end_z_mm center_x_mm center_y_mm: each programmed
//                             move's end as the report's moves give it (kind rapid, line, arc_cw, arc_ccw)
//   tool.dat                  t_s x_mm y_mm travel_mm contour_um following_um, per tool sample (thinned to the
//                             worst contour error per window on long jobs)
//   tool_zoom.dat             x_mm y_mm: the same path thinned ten times less, for the zoom panels
//   periods_<axis>.dat        period_us count: STEP periods within the axis's pulse runs
//   tie_<axis>.dat            t_s tie_ns: TIE of each edge against its run's fitted grid (worst per time bin)
//   velocity.dat              t_s commanded_mm_per_s carriage_mm_per_s: path speeds on a uniform grid (the
//                             carriage's over 5 ms or the grid step, the longer)
//   dead_time.dat             gap move inside total_ms [one column per cause, ms]: every gap of the job, between
//                             the programmed moves (inside 0, move: the one it leads into) and inside them (1)
//   series_<k>.dat            t_s value: ArchRun::series[k] (its marks in meta.json)
//   meta.json                 architecture, axes, causes, series, the job's extent, two tool samples (position,
//                             contour error, G-code line, rapid): worst_contour, the worst of the feed moves (of
//                             the rapids if there is no feed move), and contour_max, the worst of every move (the
//                             report's contour error max); and the architecture's own plots (ArchRun::plots, whose
//                             tables go to `dir` too)
void write_plot_data(const std::string& architecture, const ArchRun& run, const metrics::RunMetrics& m,
                     const std::filesystem::path& dir);

}  // namespace cnc::sim
