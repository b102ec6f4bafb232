#include "run/program_report.hpp"

#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace cnc::sim {

namespace {

constexpr std::size_t kLinesShown = 8;
constexpr host::WaitCause kCauses[] = {host::WaitCause::Dwell, host::WaitCause::OperatorPause,
                                       host::WaitCause::OtherAxes};

std::string lines_text(const std::vector<int>& lines) {
    std::string t = lines.size() == 1 ? "line " : "lines ";
    for (std::size_t k = 0; k < lines.size() && k < kLinesShown; ++k) t += (k ? ", " : "") + std::to_string(lines[k]);
    if (lines.size() > kLinesShown) t += ", ... (" + std::to_string(lines.size()) + " in all)";
    return t;
}

std::size_t wait_count(const host::Program& p, host::WaitCause cause) {
    std::size_t n = 0;
    for (const host::HostWait& w : p.waits) n += w.cause == cause ? 1 : 0;
    return n;
}

}  // namespace

nlohmann::json program_json(const host::Program& program) {
    nlohmann::json ignored = nlohmann::json::array();
    for (const host::IgnoredWord& w : program.ignored) {
        ignored.push_back({{"word", w.word}, {"count", w.lines.size()}, {"reason", w.reason}, {"lines", w.lines}});
    }
    nlohmann::json waits = nlohmann::json::object();
    for (const host::WaitCause c : kCauses) {
        waits[host::to_string(c)] = {{"count", wait_count(program, c)}, {"total_s", program.wait_s(c)}};
    }
    return {{"lines", program.lines},
            {"moves", program.move_count},
            {"ignored_by_this_machine", ignored},
            {"host_waits", waits},
            {"z_travel_mm", program.z_travel_mm}};
}

std::string program_text(const host::Program& program) {
    std::ostringstream t;
    t << "G-code: " << program.lines << " lines, " << program.move_count << " XY moves\n";
    if (!program.waits.empty()) {
        t << "  host waits (XY at rest):";
        for (const host::WaitCause c : kCauses) {
            t << fmt::format(FMT_STRING(" {} {:.3f} s ({})"), host::to_string(c), program.wait_s(c),
                             wait_count(program, c));
        }
        t << '\n';
    }
    if (program.z_travel_mm > 0.0) {
        t << fmt::format(
            FMT_STRING("  Z travel {:.3f} mm: this architecture has no Z STEP pins; a Z-only move is timed at its feed "
                       "and added as host dead time, a move with XY and Z runs its XY path at the XY share of F\n"),
            program.z_travel_mm);
    }
    if (!program.ignored.empty()) {
        t << "  ignored by this machine (scenario.gcode_policy = \"strict\" refuses them):\n";
        for (const host::IgnoredWord& w : program.ignored) {
            t << "    " << w.word << " x" << w.lines.size() << " (" << w.reason << "), " << lines_text(w.lines) << '\n';
        }
    }
    return t.str();
}

void laser_warnings(const host::ProgrammedMove& m, const std::string& filename, LaserSwitching switching,
                    std::vector<Warning>& out) {
    const std::string where = filename + ":" + std::to_string(m.line);
    const bool cutting = m.kind != host::MotionKind::Rapid;
    const bool power_on = m.laser_mode != host::LaserMode::Off && (!m.power_s || *m.power_s > 0.0);
    if (switching == LaserSwitching::ByMotionKind && cutting && !m.laser_intended()) {
        out.push_back({"laser_on_unasked", where,
                       "the laser burns where the job asked it off (M5 or S0 during G1/G2/G3): this hardware "
                       "switches it on in every cutting move"});
    }
    if (switching == LaserSwitching::ByMotionKind && !cutting && power_on) {
        out.push_back({"laser_power_in_rapid", where,
                       "the job has M3/M4 with power in force during G0: this hardware switches the laser off in "
                       "rapids (as grbl's laser mode does)"});
    }
    if (m.laser_mode == host::LaserMode::Dynamic && cutting) {
        out.push_back({"laser_m4_on_off", where,
                       "M4 (power scaled with speed) runs as plain on/off: this architecture's link carries no "
                       "power value"});
    }
}

}  // namespace cnc::sim
