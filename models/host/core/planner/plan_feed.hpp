// The spi-fpga host's plan of a job as its readers consume it: the job's moves are read (GcodeStream) and planned
// (PlanStream) only as far as the trajectory or a move is asked for, so that a long job is held as its look-ahead
// window plus what its readers have not dropped yet. Every reading equals the whole program's plan (planner.hpp)
// exactly: PlanStream hands over each piece and window bit for bit the whole program's, whenever it is taken.
#pragma once
#include <cstddef>
#include <deque>
#include <memory>
#include <utility>

#include "host/core/gcode.hpp"
#include "host/core/planner/plan_stream.hpp"
#include "host/core/planner/planner_config.hpp"
#include "host/core/planner/trajectory.hpp"

namespace cnc::host::planner {

// A programmed move with what the plan made of it.
struct FedMove {
    ProgrammedMove move;
    std::pair<double, double> window;  // as Trajectory::move_windows
    double peak_mm_per_s = 0.0;        // planned peak path speed of its own piece; 0 without one
};

class PlanFeed {
public:
    // `moves` reads the job; the waits come from its program() as they are read. BadInput as PlanStream's, thrown
    // when the move is read (a caller that must not fail mid-run plans the job once whole before).
    PlanFeed(const PlannerConfig& cfg, std::unique_ptr<GcodeStream> moves);

    // The pieces planned so far and not dropped.
    [[nodiscard]] const Trajectory& trajectory() const { return m_traj; }
    // The whole program's state at t_s (planned past t_s first).
    [[nodiscard]] Sample at(double t_s);
    // Plans until at(t_s) is final: a piece ends after t_s, or the whole job is planned.
    void plan_past(double t_s);
    // Reads and plans one more programmed move (the end of the job after the last); false once complete.
    bool plan_next();
    [[nodiscard]] bool complete() const { return m_complete; }
    // The pieces before the one at(t_s) reads (no reader goes back before t_s any more).
    void drop_before(double t_s) { m_traj.drop_before(t_s); }

    // Programmed move i (0-based, in program order) once its window is known, planning as far as that takes; null
    // past the job's last move. i must not be before the first move kept (drop_moves_before).
    [[nodiscard]] const FedMove* move(std::size_t i);
    // The moves before i are read no more (i past the last handed over: every one handed over so far).
    void drop_moves_before(std::size_t i);

private:
    void take();

    std::unique_ptr<GcodeStream> m_moves;
    PlanStream m_stream;
    Trajectory m_traj;
    bool m_complete = false;
    std::size_t m_waits_added = 0;    // of m_moves->program().waits
    std::size_t m_read = 0;           // programmed moves read
    std::deque<FedMove> m_unplanned;  // read, their window not known yet, in order
    std::deque<FedMove> m_planned;    // window known, not dropped
    std::size_t m_first_planned = 0;  // the index of m_planned.front()
};

}  // namespace cnc::host::planner
