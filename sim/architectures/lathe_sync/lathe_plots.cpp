#include "architectures/lathe_sync/lathe_plots.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include <fmt/format.h>

namespace cnc::sim::lathe_sync {

namespace {

// A colour per pass, the Okabe-Ito palette of the other plots (docs/plots.md): readable with colour-blindness.
constexpr const char* kPassColours[] = {"#0072b2", "#d55e00", "#009e73", "#cc79a7",
                                        "#e69f00", "#56b4e9", "#000000", "#f0e442"};
constexpr const char* kSettleColour = "#e8e8e8";  // light grey: the curves stay readable over it
// The carriage as a circle every 4th spindle pulse (a tenth of a revolution): the firmware's line stays visible
// beneath.
constexpr int kCarriageMarkEvery = 4;
constexpr const char* kRevolutionLabel = "spindle revolutions since the pass start index [rev]";

const char* colour(std::size_t pass) {
    return kPassColours[pass % std::size(kPassColours)];
}

double revolution(std::size_t pulse) {
    return static_cast<double>(pulse) / lathe::kSpindleSlots;
}

std::string join_plot(const std::vector<std::string>& clauses) {
    std::string out = "plot ";
    for (std::size_t i = 0; i < clauses.size(); ++i) out += (i ? ", \\\n     " : "") + clauses[i];
    return out + "\n";
}

// A tic step of 1, 2 or 5 x 10^n (n >= 0) that puts at most 10 tics on `span`.
double tic_step(double span) {
    for (double decade = 1.0;; decade *= 10.0) {
        for (const double step : {1.0, 2.0, 5.0}) {
            if (span / (step * decade) <= 10.0) return step * decade;
        }
    }
}

// Pass k against pass 1 wherever both lie inside the common length, the settling revolutions shaded (they are left
// out of the report's max), the report's max marked, a second axis in motor pulses.
std::optional<ArchPlot> phase_plot(const LathePlotInput& in) {
    if (in.passes.size() < 2) return std::nullopt;
    std::vector<lathe::ThreadPass> thread;
    for (const lathe::RecordedPass& p : in.passes) thread.push_back(p.thread);
    PlotTable table{"phase_error.dat", "revolution phase_error_um: a block per pass from pass 2, against pass 1", {}};
    double first_rev = 1e300, last_rev = 0.0, lo_um = 0.0, hi_um = 0.0;
    std::vector<std::string> clauses;
    for (std::size_t k = 1; k < thread.size(); ++k) {
        std::vector<std::vector<double>> rows;
        for (std::size_t j = 0; j < thread.front().x_mm.size(); ++j) {
            const std::optional<double> d = lathe::phase_error_um(thread, k, j, in.thread);
            if (!d) continue;
            rows.push_back({revolution(j), *d});
            first_rev = std::min(first_rev, revolution(j));
            last_rev = std::max(last_rev, revolution(j));
            lo_um = std::min(lo_um, *d);
            hi_um = std::max(hi_um, *d);
        }
        if (rows.empty()) continue;  // no common length with pass 1: gnuplot would warn of an empty block
        table.blocks.push_back(std::move(rows));
        clauses.push_back(fmt::format(
            FMT_STRING("data_dir.'/phase_error.dat' index {} using 1:2 with lines lw 1.5 lc rgb '{}' title 'pass {} - "
                       "pass 1'"),
            table.blocks.size() - 1, colour(k), k + 1));
    }
    if (clauses.empty()) return std::nullopt;
    const double um_per_pulse = in.mm_per_motor_pulse * 1000.0;
    // Room above and below the curves for the max's mark and the settling note.
    std::string script =
        fmt::format(FMT_STRING("set key outside top center horizontal\nset offsets 0, 0, graph 0.12, graph 0.05\n"
                               "set ytics nomirror\nset y2tics {1:g}\nset link y2 via y/{0:.6g} inverse y*{0:.6g}\n"
                               "set y2label 'phase error [motor pulses of {0:.2f} um]'\n"),
                    um_per_pulse, tic_step((hi_um - lo_um) / um_per_pulse));
    const double settle_rev = in.settle_revolutions;
    if (settle_rev > first_rev) {
        script += fmt::format(
            FMT_STRING("set object 1 rect from first {0:g}, graph 0 to first {1:g}, graph 1 behind fillcolor rgb '{2}' "
                       "fillstyle solid 1.0 noborder\n"
                       "set label 2 'first {3} revolutions: settling, left out of the max' at first {4:g}, graph 0.97 "
                       "right rotate by 90\n"),
            first_rev, settle_rev, kSettleColour, in.settle_revolutions, (first_rev + settle_rev) / 2.0);
    }
    const lathe::ThreadMetrics& m = in.thread;
    if (m.phase_error_max_um > 0.0) {
        const double at_rev = revolution(m.phase_error_max_pulse);
        const bool right_half = at_rev > (first_rev + last_rev) / 2.0;
        script += fmt::format(
            FMT_STRING("set label 1 'max {:+.2f} um: pass {} at revolution {:.3f}' at first {:g}, first {:g} {} point "
                       "pointtype 7 pointsize 1.5 lc rgb 'black' offset {},{} front\n"),
            m.phase_error_max_signed_um, m.phase_error_max_pass + 1, at_rev, at_rev, m.phase_error_max_signed_um,
            right_half ? "right" : "left", right_half ? "-1.2" : "1.2",
            m.phase_error_max_signed_um > 0 ? "0.8" : "-0.8");
    }
    return ArchPlot{"phase_error_passes", "Phase error of each pass against pass 1", kRevolutionLabel,
                    "phase error [um] (+: ahead of pass 1)", {std::move(table)}, script + join_plot(clauses)};
}

// Each pass's following error as the firmware counts it (the motor encoder's pulses: lines) and as the carriage
// stands (its travel in motor pulses: points), and below their difference: under one pulse from the count's steps,
// plus what lies between the encoder and the carriage (lathe.backlash_mm) and any pulse the count lost.
std::optional<ArchPlot> following_plot(const LathePlotInput& in) {
    if (in.passes.empty()) return std::nullopt;
    PlotTable table{"following_error.dat",
                    "revolution firmware_pulses carriage_pulses: a block per pass; lambda_list x k minus the motor "
                    "pulses since the pass start, minus the carriage travel since then in motor pulses",
                    {}};
    std::vector<std::string> errors, differences;
    double apart = 0.0;
    for (std::size_t i = 0; i < in.passes.size(); ++i) {
        const std::vector<double>& x_mm = in.passes[i].thread.x_mm;
        const std::vector<double>& firmware = in.following_pulses[i];
        table.blocks.emplace_back();
        for (std::size_t k = 0; k < firmware.size() && k < x_mm.size(); ++k) {
            const double carriage =
                in.lambda_list * static_cast<double>(k) - (x_mm[k] - x_mm[0]) / in.mm_per_motor_pulse;
            table.blocks.back().push_back({revolution(k), firmware[k], carriage});
            apart = std::max(apart, std::abs(firmware[k] - carriage));
        }
        const std::string file = fmt::format(FMT_STRING("data_dir.'/following_error.dat' index {}"), i);
        errors.push_back(fmt::format(FMT_STRING("{} using 1:2 with lines lw 1.5 lc rgb '{}' title 'pass {}, firmware'"),
                                     file, colour(i), i + 1));
        errors.push_back(fmt::format(
            FMT_STRING("{} every {} using 1:3 with points pt 6 ps 0.6 lc rgb '{}' title 'pass {}, carriage'"), file,
            kCarriageMarkEvery, colour(i), i + 1));
        differences.push_back(
            fmt::format(FMT_STRING("{} using 1:($2-$3) with lines lw 1.2 lc rgb '{}' notitle"), file, colour(i)));
    }
    // Two panels on one x axis: fixed margins line them up, the key stands beside the upper one.
    const double range = std::max(1.5, 1.2 * apart);
    const std::string script =
        "set multiplot\nset lmargin at screen 0.09\nset rmargin at screen 0.80\n"
        "set key at screen 0.99, screen 0.92 right top vertical\n"
        "set origin 0, 0.34\nset size 1, 0.66\nset bmargin 1.5\nunset xlabel\nset format x ''\n" +
        join_plot(errors) +
        fmt::format(FMT_STRING("unset title\nset origin 0, 0\nset size 1, 0.36\nset tmargin 1.5\nset bmargin 3.5\n"
                               "set format x '%g'\nset xlabel '{}'\nset ylabel 'firmware - carriage [pulses]'\n"
                               "set yrange [{:g}:{:g}]\nset ytics {:g}\n"),
                    kRevolutionLabel, -range, range, tic_step(2.0 * range)) +
        join_plot(differences) + "unset multiplot\n";
    return ArchPlot{"following_error_passes", "Following error of each pass: the firmware count and the carriage",
                    kRevolutionLabel, "following error [motor pulses]", {std::move(table)}, script};
}

}  // namespace

std::vector<ArchPlot> lathe_plots(const LathePlotInput& in) {
    std::vector<ArchPlot> out;
    if (std::optional<ArchPlot> p = phase_plot(in)) out.push_back(std::move(*p));
    if (std::optional<ArchPlot> p = following_plot(in)) out.push_back(std::move(*p));
    return out;
}

}  // namespace cnc::sim::lathe_sync
