// The planned motion: the pieces of path actually followed (trimmed programmed moves and corner blends), each
// with its speed profile, evaluated at any time.
#pragma once
#include <utility>
#include <vector>

#include "common/geometry.hpp"
#include "host/core/planner/curve.hpp"
#include "host/core/planner/speed_profile.hpp"

namespace cnc::host::planner {

struct Sample {
    double t_s;
    geom::Vec2 pos_mm;
    geom::Vec2 vel_mm_per_s;
    geom::Vec2 acc_mm_per_s2;
    double path_speed_mm_per_s;
    int move;  // index into Program::moves; -1 in a corner blend or at rest with nothing to do
};

struct PlannedPiece {
    Curve path;
    int move;  // the programmed move this piece is (part of), -1 for a corner blend
    double t_begin_s;
    double t_end_s;
    SpeedProfile speed;  // entry, peak and exit speed and the phase durations
};

class Trajectory {
public:
    // `move_windows` has one [t_begin, t_end] per programmed move; `rest_mm` is where the tool stands when
    // there are no pieces; `end_hold_s` the host's waits after the last piece (the tool rests). Pieces may
    // leave gaps between them (host waits): the tool rests at the end of the piece before.
    Trajectory(std::vector<PlannedPiece> pieces, std::vector<std::pair<double, double>> move_windows,
               geom::Vec2 rest_mm, double end_hold_s = 0.0);
    // A trajectory planned as it is read (plan_feed.hpp): no pieces and no move windows yet.
    Trajectory() = default;
    // The next pieces in path order, and where the tool stands before the first piece (final once a piece is known).
    void append(std::vector<PlannedPiece> pieces, geom::Vec2 rest_mm);
    void set_end_hold(double end_hold_s) { m_end_hold_s = end_hold_s; }
    // Drops the pieces before the one at(t_s) reads, so that at(t) for t >= t_s reads as before.
    void drop_before(double t_s);

    [[nodiscard]] double duration_s() const {
        return (m_pieces.empty() ? 0.0 : m_pieces.back().t_end_s) + m_end_hold_s;
    }
    // State at t, clamped to [0, duration]; O(log pieces). At a boundary time the later piece is used.
    [[nodiscard]] Sample at(double t_s) const;
    [[nodiscard]] const std::vector<PlannedPiece>& pieces() const { return m_pieces; }
    // Time span of each programmed move's own piece (none for a trajectory planned as it is read: PlanFeed hands
    // each move's window over with the move). Corner blends lie between the windows (they belong to no
    // move); a move skipped as shorter than 1e-9 mm, or consumed entirely by its two blends, gets an empty window.
    [[nodiscard]] const std::vector<std::pair<double, double>>& move_windows() const { return m_move_windows; }

private:
    std::vector<PlannedPiece> m_pieces;
    std::vector<std::pair<double, double>> m_move_windows;
    geom::Vec2 m_rest_mm{};
    double m_end_hold_s = 0.0;
};

}  // namespace cnc::host::planner
