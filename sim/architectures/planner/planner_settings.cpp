#include "architectures/planner/planner_settings.hpp"

#include <string>

namespace cnc::sim {

void read_planner_settings(KeyReader& r, const host::MachineModel& machine, host::planner::PlannerConfig& c) {
    c.profile = r.get_choice("planner.profile", "trapezoidal", {"trapezoidal", "jerk-limited"},
                             "speed profile: constant-acceleration phases, or the seed's cubic acceleration "
                             "(seed 004 §3.2)") == "trapezoidal"
                    ? host::planner::Profile::Trapezoidal
                    : host::planner::Profile::JerkLimited;
    const std::string mode =
        r.get_choice("planner.mode", "continuous", {"continuous", "exact-path", "exact-stop"},
                     "until the program sets one: continuous (G64 P: corners blended within path_tolerance_mm), "
                     "exact-path (G61: a stop at every corner) or exact-stop (G61.1: rest at every move end; seed "
                     "004 §3.2)");
    c.mode = mode == "continuous"   ? host::planner::BlendMode::Continuous
             : mode == "exact-path" ? host::planner::BlendMode::ExactPath
                                    : host::planner::BlendMode::ExactStop;
    c.path_tolerance_mm = r.get_float("planner.path_tolerance_mm", c.path_tolerance_mm, 0.0, 100.0,
                                      "largest distance of a corner blend from the corner, mm (G64 P); 0: stop");
    c.lookahead_moves = static_cast<int>(
        r.get_int("planner.lookahead_moves", c.lookahead_moves, 1, 100'000, "programmed moves the planner sees ahead"));
    c.x = machine.x.limits;  // one machine for every architecture
    c.y = machine.y.limits;
}

}  // namespace cnc::sim
