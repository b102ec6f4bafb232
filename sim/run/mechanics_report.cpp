#include "run/mechanics_report.hpp"

#include <algorithm>
#include <cstdlib>
#include <iomanip>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "metrics/laser/laser_exposure.hpp"

namespace cnc::sim {

namespace {

nlohmann::json axis_json(const mech::DynamicAxis& axis) {
    const mech::DynamicAxisStats& st = axis.stats();
    nlohmann::json times = nlohmann::json::array();
    for (const mech::LostStepEvent& e : st.events)
        times.push_back({{"t_s", ps_to_s(e.t_ps)}, {"full_steps", e.full_steps}});
    return {{"lost_full_steps", st.lost_full_steps},
            {"lost_step_events", times},
            {"peak_load_angle_electrical_deg", st.peak_load_angle_deg},
            {"peak_load_angle_t_s", ps_to_s(st.peak_load_angle_ps)},
            {"velocity_ripple_rms_mm_per_s", st.velocity_ripple_rms_mm_s},
            {"velocity_ripple_peak_mm_per_s", st.velocity_ripple_peak_mm_s},
            {"integration_steps", axis.integrator().steps_taken()}};
}

std::string axis_text(const char* name, const mech::DynamicAxisStats& st) {
    std::ostringstream t;
    t << "  " << name << ": lost " << st.lost_full_steps << " full steps";
    if (!st.events.empty()) t << fmt::format(FMT_STRING(" (first at {:.6f} s)"), ps_to_s(st.events.front().t_ps));
    t << fmt::format(
        FMT_STRING(", peak load angle {:.1f} electrical deg at {:.6f} s, velocity ripple rms {:.3f} / peak "
                   "{:.3f} mm/s\n"),
        st.peak_load_angle_deg, ps_to_s(st.peak_load_angle_ps), st.velocity_ripple_rms_mm_s,
        st.velocity_ripple_peak_mm_s);
    return t.str();
}

// A hybrid stepper's torque goes as the sine of the load angle and peaks at 90 electrical degrees (pull-out,
// docs/mechanics.md, "Outputs").
constexpr double kPullOutDeg = 90.0;

// A peak load angle near or past pull-out, as a warning: the motor had little or no torque left there, whether it
// lost steps or not. Within 10 % of pull-out, from 81, the motor already gives sin 81 = 98.8 % of its largest torque.
void load_angle_warning(const char* axis, const mech::DynamicAxisStats& st, std::vector<Warning>& out) {
    constexpr double kNearFraction = 0.9;
    const double peak = st.peak_load_angle_deg;
    if (peak < kNearFraction * kPullOutDeg) return;
    const bool past = peak > kPullOutDeg;
    std::ostringstream where, text;
    where << axis << " at " << std::fixed << std::setprecision(6) << ps_to_s(st.peak_load_angle_ps) << " s";
    text
        << "peak load angle " << std::fixed << std::setprecision(1) << peak << " electrical deg, "
        << (past ? "past pull-out (90: the motor's largest torque)" : "within 10 % of pull-out (90)") << ", with "
        << st.lost_full_steps << " full steps lost on the axis: "
        << (past
                ? "beyond the torque's peak more lag gives less torque, and the rotor keeps step only if the load eases"
                : "about 1 % of the motor's torque is left in reserve")
        << " (a lower feed or acceleration, more current, or a lighter carriage gives margin)";
    out.push_back({past ? "load_angle_past_pull_out" : "load_angle_near_pull_out", where.str(), text.str()});
}

// The load angle's peaks and the lost full steps (cumulative) over time, per axis: what the plots draw.
void add_series(const char* axis, const mech::DynamicAxisStats& st, ArchRun& run) {
    run.series.push_back({"load angle [electrical deg]",
                          axis,
                          st.load_angle_deg_trace.points(),
                          {{kPullOutDeg, "pull-out, 90 electrical deg: the motor's largest torque"}}});
    TimeSeries lost{"lost full steps [cumulative]", axis, {{0, 0.0}}, {}};
    std::int64_t total = 0;
    for (const mech::LostStepEvent& e : st.events) {
        total += std::abs(e.full_steps);
        lost.points.emplace_back(e.t_ps, static_cast<double>(total));
    }
    // Past kMaxLostStepEvents only the count goes on: the last point holds the whole of it.
    const TimePs end_ps = std::max(run.input.t_job_end_ps, lost.points.back().first);
    lost.points.emplace_back(end_ps, static_cast<double>(st.lost_full_steps));
    run.series.push_back(std::move(lost));
}

}  // namespace

void add_mechanics_report(const Machine& machine, const std::optional<MetricsFeed>& feed, ArchRun& run) {
    const mech::DynamicAxis* x = machine.dynamic_x();
    const mech::DynamicAxis* y = machine.dynamic_y();
    if (x == nullptr || y == nullptr) return;
    const metrics::LaserExposure e = feed              ? feed->laser_exposure()
                                     : run.input.laser ? metrics::laser_exposure(run.input.tool, *run.input.laser)
                                                       : metrics::LaserExposure{};
    run.details["mechanics"] = {{"model", "dynamic"},
                                {"x", axis_json(*x)},
                                {"y", axis_json(*y)},
                                {"laser_exposure",
                                 {{"lasered_path_mm", e.lasered_path_mm},
                                  {"mean_s_per_mm", e.mean_s_per_mm},
                                  {"peak_s_per_mm", e.peak_s_per_mm},
                                  {"peak_at_lasered_path_mm", e.peak_at_path_mm},
                                  {"bin_mm", metrics::kExposureBinMm}}}};
    std::ostringstream t;
    t << "Mechanics (dynamic): the carriage position above comes from the axis models; contour and following "
         "error include their lag and ringing\n"
      << axis_text("x", x->stats()) << axis_text("y", y->stats())
      << fmt::format(FMT_STRING("  laser exposure: mean {:.4f} s/mm over {:.2f} mm, peak {:.4f} s/mm ({:.1f} mm bin "
                                "at {:.2f} mm of lasered path)\n"),
                     e.mean_s_per_mm, e.lasered_path_mm, e.peak_s_per_mm, metrics::kExposureBinMm, e.peak_at_path_mm);
    run.details_text += t.str();
    add_series("x", x->stats(), run);
    add_series("y", y->stats(), run);
    load_angle_warning("X", x->stats(), run.warnings);
    load_angle_warning("Y", y->stats(), run.warnings);
}

}  // namespace cnc::sim
