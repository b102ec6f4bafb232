// The metrics of a run computed while it runs, in memory that grows with its moves and not with its steps
// (docs/streaming.md): the run appends what it recorded to pending() and calls fold() at its slice boundaries; the
// programmed moves that can no longer change are measured with the batch code (compute_metrics on them and their
// neighbours) and their edges and samples are dropped. finish() gives what compute_metrics gives on the whole run.
// With a commanded trajectory (its t_end_ps: how far it is known so far) a window is cut a sync window before its
// end, and with rate segments only where every segment with edges before the cut has ended: its run is measured
// whole with the piece of its first edge (docs/streaming.md).
#pragma once
#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include "metrics/laser/laser.hpp"
#include "metrics/laser/laser_exposure.hpp"
#include "metrics/metrics.hpp"
#include "metrics/stats.hpp"
#include "metrics/timing/move_timing.hpp"
#include "metrics/timing/worst_moves.hpp"

namespace cnc::metrics {

// Each executed piece as it is measured, in order (what an architecture reads of the pieces beyond the report).
using PieceMeasured = std::function<void(const MoveMetrics&)>;

class MetricsStream {
public:
    // `shape`: the run's axes (names, pins and their initial levels, steps per mm, polarity), its laser pin, driver
    // limits and job start, usually with no edges, samples or moves yet.
    // The programmed moves' records go to a temporary file as they are measured (move_records.hpp).
    // `detail`: keep the per-piece records and the pulse runs, which only the detailed report lists (it grows with
    // them anyway); without, finish() gives their summaries only (RunMetrics::pieces and AxisMetrics::runs empty).
    MetricsStream(RunInput shape, bool detail, PieceMeasured on_piece = {});

    // Where the run appends its edges, tool samples, laser edges and pieces in time order. A piece is appended when
    // it begins; its t_end_ps must be set before now_ps passes it. t_job_end_ps: the job's end once it is known,
    // until then a time not before now_ps.
    [[nodiscard]] RunInput& pending() { return m_in; }
    // Everything the run records before now_ps is in pending() (both pins of an axis cut at the same instant).
    void fold(TimePs now_ps);
    // The run has ended at t_job_end_ps (not before a piece it has begun): the metrics of the whole run.
    [[nodiscard]] RunMetrics finish(TimePs t_job_end_ps);
    // The laser's exposure per mm of the tool's path (the dynamic mechanics' report), once finished.
    [[nodiscard]] LaserExposure laser_exposure() const { return m_exposure.finish(); }

private:
    void measure(TimePs now_ps, bool final);
    [[nodiscard]] bool two_moves_pending() const;
    // The begin of the second programmed move past the kept neighbour: no window ends before it.
    [[nodiscard]] TimePs earliest_cut_ps() const;
    // Whether an axis has a STEP rise before before_ps in its last known rate segment (one with no next yet).
    [[nodiscard]] bool step_in_open_segment(TimePs before_ps) const;
    // Whether the window may end at cut_ps: the commanded trajectory known around it, no rate segment across it.
    [[nodiscard]] bool cut_allowed(const RunMetrics& r, TimePs cut_ps, TimePs now_ps) const;
    // The first window's edges before the first piece that no commanded step crossing matches.
    void count_unattributed_unmatched(const RunMetrics& r);
    // Counts the edges before cut_ps (driver timing too) and drops them from pending().
    void take_edges_before(TimePs cut_ps, bool first_fold, const RunMetrics& r);
    // Drops the rate segments whose runs are measured or have no edges.
    void drop_rate_segments(const RunMetrics& r, TimePs cut_ps);
    // Drops the measured pieces but the last (a contour neighbour) and the samples but the last before cut_ps.
    void drop_before(TimePs cut_ps, std::size_t cut_piece);
    // Folds the laser figures up to horizon_ps and drops the laser edges, rapid windows and slow stretches read.
    void fold_laser(TimePs horizon_ps);
    // Folds the exposure over the tool samples [first_sample, end_sample) of pending().
    void fold_exposure(std::size_t first_sample, std::size_t end_sample);

    RunInput m_in;
    bool m_detail;
    PieceMeasured m_on_piece;
    bool m_has_prev = false;         // m_in.moves.front() is the last measured piece, kept as a contour neighbour
    bool m_sample_measured = false;  // m_in.tool.front() was measured, kept as the sample before the window
    std::size_t m_pieces_done = 0;   // measured pieces
    std::size_t m_moves_done = 0;    // measured programmed moves
    bool m_rate_segmented = false;   // runs are per rate segment (RunMetrics::runs_per_rate_segment)
    std::vector<std::size_t> m_rising_done;  // [axis] rising edges dropped
    std::vector<AxisMetrics> m_axes;         // counts, runs (detail), sync of the measured part
    std::vector<PulseSummaryFold> m_pulse;   // [axis]
    std::vector<DriverTimingStream> m_driver;
    std::optional<TimePs> m_first_edge_ps, m_last_edge_ps;  // any axis
    RunMetrics m_out;                                       // pieces, moves, sync and endpoint extrema so far
    MaxRms m_contour, m_following;
    WorstMovesFold m_worst;
    TimingFold m_timing;
    std::vector<TimeInterval> m_rapid;
    SlowStretches m_slow;
    std::optional<TimePs> m_last_sample_ps;  // the last tool sample measured
    LaserFold m_laser;
    LaserExposureFold m_exposure;
};

}  // namespace cnc::metrics
