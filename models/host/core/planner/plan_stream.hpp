// The planner (planner.hpp) fed a programmed move at a time: each piece is handed over as soon as its speed
// profile is final, that is once the moves its look-ahead window needs have been read (lookahead.hpp), so a long
// job is planned in chunks as it is read and only the window is held. The pieces, their times and the moves'
// windows equal the whole program's plan exactly (the same operations in the same order) whenever they are taken:
// everything read before the first take is the whole program planned in one pass.
#pragma once
#include <cstddef>
#include <deque>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "host/core/gcode.hpp"
#include "host/core/planner/lookahead.hpp"
#include "host/core/planner/planner_config.hpp"
#include "host/core/planner/trajectory.hpp"

namespace cnc::host::planner {

// The path control in force at the end of a programmed move (LinuxCNC's segment end condition).
struct JoinControl {
    BlendMode mode;
    std::optional<double> tolerance_mm;  // Continuous: G64 P; none: G64 without P (only the moves' lengths bound it)
};

class PlanStream {
public:
    // BadInput for an invalid configuration (validate(cfg, "planner")); `filename` names the job in messages.
    PlanStream(const PlannerConfig& cfg, std::string filename);

    // In the program's order: each host wait (Program::waits, in their order) before the move it precedes, then
    // the move; the waits after the last move before finish(). BadInput for a cutting move without a positive feed.
    void add_wait(double seconds) { m_waits_s += seconds; }
    void add_move(const ProgrammedMove& move);
    void finish();

    // The pieces whose profile is final, in path order, not taken yet. Their speeds are worked out here, over all
    // that has been read: a whole program read before the first take is planned in one pass.
    [[nodiscard]] std::vector<PlannedPiece> take_pieces();
    // The windows (Trajectory::move_windows) of the programmed moves, in order, known and not taken yet.
    [[nodiscard]] std::vector<std::pair<double, double>> take_windows();
    // Where the tool stands before the first piece: final once a piece has been taken, or after finish().
    [[nodiscard]] geom::Vec2 rest_mm() const {
        return m_first_kept_start_mm.value_or(m_first_start_mm.value_or(geom::Vec2{}));
    }
    // After finish(): the host's waits after the last piece.
    [[nodiscard]] double end_hold_s() const { return m_end_hold_s; }

    // A programmed move the planner keeps (not shorter than 1e-9 mm), as the joins see it.
    struct KeptMove {
        int move;
        Curve curve;
        double feed_mm_per_s;
        double wait_before_s;  // host waits (dwell, pause, Z move) since the kept move before: the tool rests
        bool rapid;
        JoinControl control;       // at its end
        bool kink_before = false;  // a G61 corner stop at its start / end (plan_stream.cpp, Join::kink)
        bool kink_after = false;
    };

private:
    // A piece laid out, before its speeds are known.
    struct Draft {
        Curve path;
        int move;
        double feed_mm_per_s;
        double wait_before_s;
        PathLimits limits;  // set by add_draft
    };
    // Where a move's window comes from: its own piece, or (no piece) the start of piece `piece`.
    struct WindowSource {
        std::size_t piece;
        bool own;
    };

    void lay_out(const KeptMove& kept, const std::optional<Curve>& after, bool stop_after, const KeptMove* next);
    // `finalized`: a move follows it in the queue (path_limits.hpp); `accel_scale` scales its path acceleration.
    void add_draft(Draft d, bool stop_before, int last_move_needed, bool finalized, double accel_scale);
    void schedule(bool ended);

    PlannerConfig m_cfg;
    std::string m_filename;
    int m_moves_read = 0;
    bool m_finished = false;
    double m_waits_s = 0.0;                           // since the last kept move
    std::optional<geom::Vec2> m_first_start_mm;       // of the first move
    std::optional<geom::Vec2> m_first_kept_start_mm;  // of the first kept move
    std::optional<KeptMove> m_last_kept;              // waiting for the join after it
    std::optional<Curve> m_blend_before;              // the blend at the last kept move's start
    int m_next_unassigned = 0;   // moves before a kept one were skipped: empty window where it starts
    bool m_stop_pending = true;  // the program starts at rest
    std::size_t m_drafts = 0;    // laid out so far
    std::optional<double> m_prev_velocity_mm_per_s;  // the last draft's speed limit
    Lookahead m_look;
    std::deque<Draft> m_unscheduled;     // drafts whose exit speed is not final yet
    std::deque<WindowSource> m_sources;  // windows not known yet, in move order
    std::size_t m_scheduled = 0;
    double m_t_s = 0.0;  // the end of the last piece scheduled
    double m_entry_mm_per_s = 0.0;
    std::vector<PlannedPiece> m_pieces;
    std::vector<std::pair<double, double>> m_windows;
    double m_end_hold_s = 0.0;
};

}  // namespace cnc::host::planner
