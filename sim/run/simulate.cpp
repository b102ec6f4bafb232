#include "run/simulate.hpp"

#include <algorithm>
#include <iostream>

#include <fmt/format.h>

#include "common/sc_time.hpp"
#include "run/timed_progress.hpp"

namespace cnc::sim {

namespace {

// Adaptive slices (no `finished` check): start at 10 ms of simulated time and keep each slice between these
// wall times, so that the display updates a few times a second and sc_start is called rarely.
constexpr TimePs kFirstSlicePs = 10 * kPsPerMs;
constexpr double kSliceWallMinS = 0.05;
constexpr double kSliceWallMaxS = 0.2;
// ... and at most this much simulated time: the streaming metrics hold a slice's edges and samples until it ends,
// so memory must not depend on how fast the machine ran the slices before (a slice doubled in a light stretch of a
// job held 30 MiB of a raster's edges). At 200x real time this is 5 ms of wall time.
constexpr TimePs kSliceMaxPs = kPsPerSec;
// The largest scenario.max_sim_s (11.6 days), also for a job whose estimate is longer: TimePs holds 106 days.
constexpr double kMaxLimitS = 1e6;

}  // namespace

RunBudget run_budget(const Scenario& s, const JobEstimate& estimate) {
    RunBudget b;
    b.estimate = estimate;
    b.limit_from_scenario = s.max_sim_s.has_value();
    const double limit_s = std::min(s.max_sim_s.value_or(estimate.limit_s), kMaxLimitS);
    b.limit_ps = static_cast<TimePs>(limit_s * static_cast<double>(kPsPerSec));
    b.progress = s.progress;
    b.label = s.architecture;
    return b;
}

SimulationEnd simulate(const RunBudget& budget, const std::function<bool()>& finished, TimePs check_ps,
                       const std::function<void(TimePs)>& after_slice) {
    TimedProgress progress(std::cerr, budget.progress, budget.estimate.expected_s, budget.label);
    // A model asked every check_ps never starves (an MCU's timers run on): each slice runs to its end, as
    // one bounded sc_start per check always did. Otherwise a slice stops at its last event, as one
    // sc_start(limit, SC_EXIT_ON_STARVATION) would, so that the run ends where the model went quiet.
    const sc_core::sc_starvation_policy policy =
        check_ps > 0 ? sc_core::SC_RUN_TO_TIME : sc_core::SC_EXIT_ON_STARVATION;
    TimePs slice_ps = check_ps > 0 ? check_ps : kFirstSlicePs;
    SimulationEnd end;
    for (bool started = false;; started = true) {
        end.t_ps = now_ps();
        if (finished && finished()) break;
        TimePs until_ps = std::min(end.t_ps + slice_ps, budget.limit_ps);
        if (check_ps == 0 && started) {                  // before the first sc_start no process has been scheduled yet
            if (!sc_core::sc_pending_activity()) break;  // nothing left to happen: the model has run to its end
            // A slice must reach the next event, or the kernel would not move (and say so).
            const TimePs next_ps = end.t_ps + static_cast<TimePs>(sc_core::sc_time_to_pending_activity().value());
            if (next_ps > budget.limit_ps) {
                end.limit_reached = true;
                break;
            }
            until_ps = std::max(until_ps, next_ps);
        } else if (end.t_ps >= budget.limit_ps) {
            end.limit_reached = true;
            break;
        }
        const double slice_start_s = progress.wall_s();
        sc_core::sc_start(ps_time(until_ps - end.t_ps), policy);
        if (after_slice) after_slice(now_ps());
        progress.update(ps_to_s(now_ps()));
        if (check_ps == 0) {
            const double slice_wall_s = progress.wall_s() - slice_start_s;
            if (slice_wall_s < kSliceWallMinS) slice_ps = std::min({2 * slice_ps, budget.limit_ps, kSliceMaxPs});
            if (slice_wall_s > kSliceWallMaxS && slice_ps > 1) slice_ps /= 2;
        }
    }
    progress.finish(ps_to_s(end.t_ps));
    return end;
}

void record_budget(const RunBudget& budget, ArchRun& run) {
    run.estimated_s = budget.estimate.expected_s;
    run.max_sim_s = ps_to_s(budget.limit_ps);
}

std::string time_limit_text(const RunBudget& budget, const SimulationEnd& end) {
    const std::string stopped = fmt::format(FMT_STRING("stopped at {:.3f} s of simulated time by "), ps_to_s(end.t_ps));
    const double limit_s = ps_to_s(budget.limit_ps);
    if (budget.limit_from_scenario) {
        return stopped + fmt::format(FMT_STRING("scenario.max_sim_s = {:g} s (this job's estimate: {:.3f} s); raise "
                                                "scenario.max_sim_s"),
                                     limit_s, budget.estimate.expected_s);
    }
    return stopped +
           fmt::format(FMT_STRING("this job's limit, {:.3f} s = {} from its {:.3f} s estimate; set scenario.max_sim_s "
                                  "higher"),
                       limit_s, limit_formula(budget.estimate), budget.estimate.expected_s);
}

}  // namespace cnc::sim
