#include "architectures/lathe_sync/lathe_sync.hpp"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "architectures/lathe_sync/lathe_plots.hpp"
#include "architectures/lathe_sync/lathe_settings.hpp"
#include "architectures/lathe_sync/lathe_trace.hpp"
#include "lathe/core/lcd_transcript.hpp"
#include "lathe/core/ratio_list.hpp"
#include "lathe/core/thread_metrics.hpp"
#include "lathe/rig/lathe_rig.hpp"
#include "metrics/metrics.hpp"
#include "run/arch_run.hpp"
#include "run/timed_progress.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim::lathe_sync {

namespace {

// A following error that rises faster than this over the second half of a pass is growing, not settling: the
// seed's loop settles with its slow pole (-1.17 s^-1, from the model and gains of §4.3), so a bounded error falls
// there.
constexpr double kGrowingPulsesPerS = 10.0;
// The progress display follows the run this often (simulated time): a few times a second of wall time at the
// rig's speed of about real time.
constexpr double kProgressSliceS = 0.05;

const char* firmware_elf(const LatheSettings& s) {
    if (s.as_printed_list) return CNC_LATHE_SYNC_AS_PRINTED_ELF;
    return s.atomic_pulse_isrs ? CNC_LATHE_SYNC_ATOMIC_ELF : CNC_LATHE_SYNC_ELF;
}

// lambda_list x k - the motor pulses since the pass's start, at each spindle pulse k (the firmware's Error
// without the slip it starts from).
std::vector<double> following_error(const lathe::RecordedPass& p, double lambda) {
    std::vector<double> e;
    for (std::size_t k = 0; k < p.motor_pulses.size(); ++k) {
        e.push_back(lambda * static_cast<double>(k) - static_cast<double>(p.motor_pulses[k] - p.motor_pulses[0]));
    }
    return e;
}

// Least-squares slope of the following error against time over the second half of the pass, pulses/s.
double trend_per_s(const std::vector<double>& e, double spindle_pulse_s) {
    const std::size_t from = e.size() / 2;
    double n = 0.0, st = 0.0, se = 0.0, stt = 0.0, ste = 0.0;
    for (std::size_t k = from; k < e.size(); ++k) {
        const double t = static_cast<double>(k) * spindle_pulse_s;
        n += 1.0;
        st += t;
        se += e[k];
        stt += t * t;
        ste += t * e[k];
    }
    const double den = n * stt - st * st;
    return n < 2.0 || den <= 0.0 ? 0.0 : (n * ste - st * se) / den;
}

std::string fixed(double v, int decimals) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

// Each screen the LCD settled on, with its time: the operator's view of the run.
void report_lcd(lathe::LatheRig& rig, nlohmann::json& d, std::ostringstream& text) {
    nlohmann::json screens = nlohmann::json::array();
    text << "LCD transcript (each screen the display settled on, " << fixed(lathe::kLcdSettleS * 1000.0, 0)
         << " ms or more):\n";
    for (const lathe::LcdScreen& screen : rig.lcd_screens()) {
        screens.push_back({{"t_s", screen.t_s}, {"lines", {screen.lines[0], screen.lines[1]}}});
    }
    text << lathe::transcript_text(rig.lcd_screens());
    d["lcd_transcript"] = screens;
}

// How long the operator's script runs the rig: the length of the run, exactly (the progress display's 100 %).
double script_s(const std::vector<OperatorStep>& steps) {
    double total_s = 0.0;
    for (const OperatorStep& step : steps) {
        total_s += step.hold_s + static_cast<double>(step.keys.size()) * (lathe::kKeyHeldS + lathe::kKeyReleasedS) +
                   step.wait_s;
    }
    return total_s;
}

// Where the phase error's max lies, for the summary: which pass, which way, at which spindle revolution.
std::string phase_max_where(const lathe::ThreadMetrics& m) {
    if (m.phase_error_max_um <= 0.0) return "";
    return " (pass " + std::to_string(m.phase_error_max_pass + 1) +
           (m.phase_error_max_signed_um > 0.0 ? " ahead of" : " behind") + " pass 1 at revolution " +
           fixed(static_cast<double>(m.phase_error_max_pulse) / lathe::kSpindleSlots, 3) + ")";
}

void run_operator(lathe::LatheRig& rig, const std::vector<OperatorStep>& steps, TimedProgress& progress) {
    rig.on_slice(kProgressSliceS, [&progress](double now_s) { progress.update(now_s); });
    for (const OperatorStep& step : steps) {
        if (step.held != 0) rig.hold(step.held, step.hold_s);
        if (!step.keys.empty()) rig.type(step.keys);
        if (step.wait_s > 0.0) rig.run_for(step.wait_s);
    }
    progress.finish(rig.now_s());
}

}  // namespace

ArchRun Entry::run(const Scenario& scenario, const Job&) {
    const LatheSettings& s = scenario.settings<LatheSettings>();
    lathe::LatheRigConfig cfg;
    cfg.firmware_elf = firmware_elf(s);
    cfg.spindle_rpm = s.spindle_rpm;
    if (s.second_pole_per_s > 0.0) cfg.motor = lathe::derive_motor(s.second_pole_per_s);
    cfg.train.backlash_mm = s.backlash_mm;
    cfg.spindle.droop_pct_per_nm = s.spindle_droop_pct_per_nm;
    cfg.spindle.time_constant_s = s.spindle_time_constant_s;
    cfg.cut = {s.cut_depth_mm, s.cut_kc_n_per_mm2, s.workpiece_diameter_mm};
    cfg.feed_mm_per_rev = s.pitch_centi_mm / 100.0;
    cfg.trace_pins = !scenario.vcd_path.empty();
    cfg.record_carriage = scenario.keep_run_input;
    cfg.clock = clock_deviation(s.clock, scenario.seed);
    cfg.fast_forward = s.fast_forward;
    lathe::LatheRig rig(cfg);
    std::optional<LatheTrace> trace;
    if (cfg.trace_pins) trace.emplace(scenario, rig.chip.clock().grid_hz());
    TimedProgress progress(std::cerr, scenario.progress, script_s(s.operator_steps), scenario.architecture);
    run_operator(rig, s.operator_steps, progress);
    if (trace) trace->write(rig);

    ArchRun out;
    // The carriage for --samples only: the XY metrics have no moves to measure it against.
    out.input.tool = std::move(rig.carriage_samples);
    out.metrics = metrics::compute_metrics(metrics::RunInput{});
    if (trace) {
        out.trace = trace->layout();
        // The save file zooms on the first pass under the PID.
        if (!rig.passes.empty()) {
            const lathe::RecordedPass& p = rig.passes.front();
            out.first_move = TimeSpan{s_to_ps(p.start_s), s_to_ps(p.start_s + p.pid_s)};
        }
    }
    out.clock = oscillator_json(s.clock, rig.chip.clock());
    out.clock_text = oscillator_text(s.clock, rig.chip.clock());
    nlohmann::json& d = out.details;
    std::ostringstream text;
    text << "lathe-sync: " << s.mode << " at " << fixed(s.spindle_rpm, 1) << " rpm, firmware "
         << (s.as_printed_list ? "with makelist as printed" : "with the intended makelist") << ", pulse ISRs "
         << (s.atomic_pulse_isrs ? "atomic" : "nested (seed)") << "; " << fixed(rig.now_s(), 3) << " s simulated\n";
    d["mode"] = s.mode;
    d["spindle_rpm"] = s.spindle_rpm;
    d["pulse_isrs"] = s.atomic_pulse_isrs ? "atomic" : "nested";
    d["simulated_s"] = rig.now_s();

    if (s.mode == "tuning") {
        const std::vector<std::uint8_t> ee = rig.chip.eeprom();
        const bool written = ee.size() > 419 && ee[419] != 0xFF;
        d["tuning_record_written"] = written;
        if (written) {
            double sum = 0.0;
            for (std::size_t i = 320; i < 420; ++i) sum += ee[i];
            // (OCR2 + 1) x 32 / 8 MHz, the hardware CTC (the thesis's unit in §4.3 leaves out the + 1)
            const double unit_us = (ee[18] + 1) * 4.0;
            d["tuning_ocr2"] = ee[18];
            d["tuning_steady_counts"] = sum / 100.0;
            d["tuning_steady_period_us"] = sum / 100.0 * unit_us;
            text << "tuning record: OCR2 = " << int{ee[18]} << ", last 100 periods " << fixed(sum / 100.0, 2)
                 << " counts = " << fixed(sum / 100.0 * unit_us, 1) << " us per motor pulse\n";
        } else {
            out.ok = false;
            out.failure = "the tuning record was not written to EEPROM within the operator script's time";
        }
        report_lcd(rig, d, text);
        out.details_text = text.str();
        return out;
    }

    const lathe::RatioList list = lathe::make_ratio_list(
        s.pitch_centi_mm, s.as_printed_list ? lathe::MakelistMode::AsPrinted : lathe::MakelistMode::Intended);
    const double pitch_mm = s.pitch_centi_mm / 100.0;
    d["ratio_list"] = {{"num", list.num},
                       {"den", list.den},
                       {"lambda_exact", list.lambda_exact},
                       {"lambda_error", list.lambda_error},
                       {"pitch_produced_mm", list.pitch_produced_mm},
                       {"residual_um_per_rev", (list.pitch_produced_mm - pitch_mm) * 1000.0}};
    text << "ratio list: " << list.num << "/" << list.den << " (lambda error " << list.lambda_error << "), pitch cut "
         << fixed(list.pitch_produced_mm, 6) << " mm for " << fixed(pitch_mm, 2) << " mm\n";

    const double torque_nm = lathe::cutting_torque_nm(cfg.cut, cfg.feed_mm_per_rev);
    const double droop_rpm = s.spindle_rpm * s.spindle_droop_pct_per_nm / 100.0 * torque_nm;
    d["cutting_load"] = {{"torque_nm", torque_nm}, {"spindle_droop_steady_rpm", droop_rpm}};
    text << "cutting load: " << fixed(s.cut_depth_mm, 2) << " mm deep x " << fixed(cfg.feed_mm_per_rev, 2)
         << " mm/rev at " << fixed(s.cut_kc_n_per_mm2, 0) << " N/mm^2 on " << fixed(s.workpiece_diameter_mm, 1)
         << " mm: " << fixed(torque_nm, 3) << " N m, the spindle " << fixed(droop_rpm, 3)
         << " rpm slower once settled\n";

    const double mm_per_motor_pulse = lathe::DriveTrain(cfg.train).mm_per_motor_rev() / lathe::kMotorSlots;
    std::vector<lathe::ThreadPass> thread;
    nlohmann::json passes = nlohmann::json::array();
    const double spindle_pulse_s = 60.0 / s.spindle_rpm / lathe::kSpindleSlots;
    std::vector<std::vector<double>> following;  // per pass
    bool growing = false;
    double at_full_s = 0.0;
    for (const lathe::RecordedPass& p : rig.passes) {
        thread.push_back(p.thread);
        following.push_back(following_error(p, list.lambda_list));
        const std::vector<double>& e = following.back();
        const double max_e = e.empty() ? 0.0 : *std::max_element(e.begin(), e.end());
        const bool overshoot_measured = p.overshoot_mm >= 0.0;  // RecordedPass leaves -1 when it has none
        const double overshoot_pulses = p.overshoot_mm / mm_per_motor_pulse;
        const double trend = trend_per_s(e, spindle_pulse_s);
        growing = growing || trend > kGrowingPulsesPerS;
        at_full_s += p.at_full_s;
        passes.push_back({{"start_s", p.start_s},
                          {"pid_s", p.pid_s},
                          {"pid_at_1023_s", p.at_full_s},
                          {"pid_at_0_s", p.at_zero_s},
                          {"spindle_min_rpm", p.spindle_min_rpm},
                          {"following_error_max_pulses", max_e},
                          {"following_error_trend_pulses_per_s", trend},
                          {"overshoot_after_brake_pulses",
                           overshoot_measured ? nlohmann::json(overshoot_pulses) : nlohmann::json(nullptr)}});
        if (scenario.detail) {  // the data of the phase and following error plots (docs/metrics.md "Lathe")
            passes.back()["carriage_at_spindle_pulses_mm"] = p.thread.x_mm;
            passes.back()["motor_pulses_at_spindle_pulses"] = p.motor_pulses;
        }
        text << "pass " << passes.size() << ": " << fixed(p.pid_s, 3) << " s under the PID, at 1023 for "
             << fixed(p.at_full_s, 3) << " s, at 0 for " << fixed(p.at_zero_s, 3) << " s; following error max "
             << fixed(max_e, 1) << " pulses, trend " << fixed(trend, 1) << " pulses/s; overshoot after the brake "
             << (overshoot_measured ? fixed(overshoot_pulses, 1) + " pulses" : std::string("-")) << "; spindle down to "
             << fixed(p.spindle_min_rpm, 3) << " rpm\n";
    }
    d["passes"] = passes;
    const lathe::ThreadMetrics m = lathe::thread_metrics(thread, pitch_mm, lathe::kSpindleSlots, s.settle_revolutions);
    const lathe::ThreadMetrics whole = lathe::thread_metrics(thread, pitch_mm, lathe::kSpindleSlots);
    const bool has_phase = m.phase_error_max_um > 0.0;  // else no pass differs from pass 1: no place to name
    d["thread"] = {
        {"settle_revolutions", s.settle_revolutions},
        {"revolutions", m.revolutions},
        {"pitch_error_mean_um", m.pitch_error_mean_um},
        {"pitch_error_max_um", m.pitch_error_max_um},
        {"pitch_fit_error_um", m.pitch_fit_error_um},
        {"pitch_fit_error_pct", m.pitch_fit_error_um / (pitch_mm * 10.0)},
        {"phase_error_max_um", m.phase_error_max_um},
        {"phase_error_end_um", m.phase_error_end_um},
        {"phase_error_max_whole_pass_um", whole.phase_error_max_um},
        {"phase_error_max_signed_um", m.phase_error_max_signed_um},
        {"phase_error_max_pass", has_phase ? nlohmann::json(m.phase_error_max_pass + 1) : nullptr},
        {"phase_error_max_revolution",
         has_phase ? nlohmann::json(static_cast<double>(m.phase_error_max_pulse) / lathe::kSpindleSlots) : nullptr},
        {"common_from_mm", m.common_from_mm},
        {"common_to_mm", m.common_to_mm}};
    if (scenario.keep_run_input) {
        out.plots = lathe_plots({rig.passes, following, m, s.settle_revolutions, list.lambda_list, mm_per_motor_pulse});
    }
    d["following_error_grows"] = growing;
    d["pid_at_1023_s"] = at_full_s;
    text << "thread (" << rig.passes.size() << " passes, first " << s.settle_revolutions
         << " revolutions of each left out): pitch error mean " << fixed(m.pitch_error_mean_um, 2) << " um, max "
         << fixed(m.pitch_error_max_um, 2) << " um per revolution; fitted pitch error "
         << fixed(m.pitch_fit_error_um, 3) << " um (" << fixed(m.pitch_fit_error_um / (pitch_mm * 10.0), 4)
         << " %); phase error between passes max " << fixed(m.phase_error_max_um, 2) << " um" << phase_max_where(m)
         << ", at the end " << fixed(m.phase_error_end_um, 2) << " um (whole passes: max "
         << fixed(whole.phase_error_max_um, 2) << " um)\n";
    if (growing) {
        text << "the following error GROWS: the spindle is faster than the motor can follow (the PID output sat at "
                "its clamp 1023 for "
             << fixed(at_full_s, 3) << " s)\n";
        out.warnings.push_back({"lathe_following_error_grows", "",
                                "the following error grows over the pass: the spindle is faster than the leadscrew "
                                "motor can follow at this pitch"});
    }
    if (rig.passes.empty()) {
        out.ok = false;
        out.failure = "no cutting pass ran within the operator script";
    }
    report_lcd(rig, d, text);
    out.details_text = text.str();
    return out;
}

}  // namespace cnc::sim::lathe_sync
