#include "architectures/planner/planner_settings.hpp"

namespace cnc::sim {

void read_planner_settings(KeyReader& r, const host::MachineModel& machine, host::planner::PlannerConfig& c) {
    c.profile = r.get_choice("planner.profile", "trapezoidal", {"trapezoidal", "jerk-limited"},
                             "speed profile: constant-acceleration phases, or the seed's cubic acceleration "
                             "(seed 004 §3.2)") == "trapezoidal"
                    ? host::planner::Profile::Trapezoidal
                    : host::planner::Profile::JerkLimited;
    c.mode = r.get_choice("planner.mode", "continuous", {"continuous", "exact-stop"},
                          "continuous (G64 P: corners blended within path_tolerance_mm) or exact-stop (G61: rest "
                          "at every move end; seed 004 §3.2)") == "continuous"
                 ? host::planner::BlendMode::Continuous
                 : host::planner::BlendMode::ExactStop;
    c.path_tolerance_mm = r.get_float("planner.path_tolerance_mm", c.path_tolerance_mm, 0.0, 100.0,
                                      "largest distance of a corner blend from the corner, mm (G64 P); 0: stop");
    c.lookahead_moves = static_cast<int>(
        r.get_int("planner.lookahead_moves", c.lookahead_moves, 1, 100'000, "programmed moves the planner sees ahead"));
    c.x = machine.x.limits;  // one machine for every architecture
    c.y = machine.y.limits;
}

}  // namespace cnc::sim
