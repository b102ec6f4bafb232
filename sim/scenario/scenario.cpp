#include "scenario/scenario.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "architectures/catalog.hpp"
#include "common/bad_input.hpp"
#include "common/units.hpp"
#include "host/core/soft_limits.hpp"
#include "host/core/tool_table.hpp"
#include "metrics/vcd/vcd_timescale.hpp"
#include "scenario/cam_settings.hpp"

namespace cnc::sim {

namespace {

namespace fs = std::filesystem;

const char* const kMachineDoc =
    "machine file, relative to the scenario: a TOML file of [machine], [driver], [motor] and [mechanics] tables "
    "(`cncsim init` writes one); the scenario's own keys of those tables override it; empty: none";
// The keys that describe an axis's motor and transmission, from which its steps/mm follows.
constexpr const char* kTransmissionKeys[] = {"step_angle_deg", "transmission", "pulley_teeth", "belt_pitch_mm",
                                             "lead_mm",        "screw_starts", "gear_ratio"};

// A calibrated steps/mm given together with motor or transmission keys must be the value they imply: two
// different numbers for one axis are a mistake in the scenario, not a choice. microsteps alone does not count:
// it straps the MODE pins whatever steps/mm is.
void check_calibration(const KeyReader& r, const std::string& p, const host::AxisMachine& m) {
    if (!m.calibrated_steps_per_mm) return;
    std::string given;
    for (const char* key : kTransmissionKeys) {
        if (r.has(p + key)) given += (given.empty() ? "" : ", ") + p + key;
    }
    if (given.empty()) return;
    if (r.has(p + "microsteps")) given += ", " + p + "microsteps";
    const double calibrated = *m.calibrated_steps_per_mm;
    const double implied = m.transmission_steps_per_mm();
    constexpr double kRelativeTolerance = 1e-9;  // rounding of a value typed as a decimal, not a real difference
    if (std::abs(calibrated - implied) <= kRelativeTolerance * std::max(calibrated, implied)) return;
    r.fail(p + "steps_per_mm",
           fmt::format(FMT_STRING("{:.10g} differs from the {:.10g} steps/mm that "), calibrated, implied) + given +
               " give (with the defaults of the keys not set); "
               "give steps_per_mm alone, or values that agree");
}

// The dynamic motor turns steps_per_mm / microsteps full steps per mm. A steps_per_mm given alone (grbl's $100,
// which counts microsteps) leaves that to the default 1/32 mode, which the user did not choose: 80 steps/mm would
// run the motor at 2.5 full steps per mm instead of the 5 of a 1/16 machine, and load it twice as hard. Refused,
// naming what fixes it, rather than guessed from a transmission the user did not describe either.
void check_full_steps(const KeyReader& r, const std::string& p, const host::AxisMachine& m) {
    if (!m.calibrated_steps_per_mm || r.has(p + "microsteps")) return;
    for (const char* key : kTransmissionKeys) {
        if (r.has(p + key)) return;  // check_calibration holds steps_per_mm to what they give
    }
    const double spm = *m.calibrated_steps_per_mm;
    std::ostringstream t;
    t << spm << " steps/mm without " << p
      << "microsteps: the dynamic motor (mechanics.model = \"dynamic\") turns steps_per_mm / microsteps full steps "
         "per mm, "
      << spm / m.microsteps << " at the default 1/" << m.microsteps << "; set " << p
      << "microsteps to the driver's mode (DRV8825 MODE pins: 1, 2, 4, 8, 16 or 32; a grbl $100 counts microsteps)";
    // What the motor and transmission defaults would need, when that is a DRV8825 mode: a hint, not a choice.
    const double mode = spm / (m.transmission_steps_per_mm() / m.microsteps);
    for (const int allowed : {1, 2, 4, 8, 16, 32}) {
        if (std::abs(mode - allowed) < 1e-9 * allowed) {
            t << " (" << allowed << " gives " << spm << " steps/mm on the default " << m.step_angle_deg
              << " deg motor and " << m.travel_per_rev_mm() << " mm per revolution)";
        }
    }
    t << ", or the motor and transmission keys instead of steps_per_mm, or mechanics.model = \"ideal\"";
    r.fail(p + "steps_per_mm", t.str());
}

// An axis limit of 0 would leave the planner without a profile: refused by name rather than as a range.
double positive(KeyReader& r, const std::string& key, double def, double max, const std::string& doc,
                const std::string& why_zero) {
    const double v = r.get_float(key, def, 0.0, max, doc);
    if (!(v > 0.0)) r.fail(key, "must be > 0: " + why_zero);
    return v;
}

void read_axis_limits(KeyReader& r, const std::string& axis, host::AxisLimits& lim) {
    const std::string p = "machine." + axis + ".";
    lim.max_velocity_mm_per_s =
        positive(r, p + "max_velocity_mm_per_s", lim.max_velocity_mm_per_s, 1e5,
                 "axis velocity limit, mm/s, > 0 (LinuxCNC MAX_VELOCITY): every architecture holds its moves to it",
                 "an axis that may not move cannot follow any move");
    lim.max_accel_mm_per_s2 = positive(
        r, p + "max_accel_mm_per_s2", lim.max_accel_mm_per_s2, 1e7,
        "axis acceleration limit, mm/s^2, > 0 (LinuxCNC MAX_ACCELERATION): the trajectory planner's and the FPGA "
        "ramp's (fpga.ramp); a controller without ramps steps at full rate from the first step",
        "an axis that cannot accelerate never leaves rest");
    lim.max_jerk_mm_per_s3 =
        positive(r, p + "max_jerk_mm_per_s3", lim.max_jerk_mm_per_s3, 1e10,
                 "axis jerk limit, mm/s^3, > 0 (planner.profile = jerk-limited and fpga.ramp = \"s-curve\" only)",
                 "a jerk-limited profile could never change its acceleration");
}

void read_axis(KeyReader& r, const std::string& axis, host::AxisMachine& m) {
    const std::string p = "machine." + axis + ".";
    m.step_angle_deg = r.get_float(p + "step_angle_deg", m.step_angle_deg, 0.01, 90.0,
                                   "motor full-step angle, degrees (42BYGHW208: 1.8)");
    m.microsteps = static_cast<int>(
        r.get_int(p + "microsteps", m.microsteps, 1, 32, "DRV8825 microstep mode: 1, 2, 4, 8, 16 or 32 (MODE pins)"));
    const std::string tr =
        r.get_choice(p + "transmission", "belt", {"belt", "leadscrew"}, "belt and pulley, or leadscrew");
    m.transmission = tr == "belt" ? host::Transmission::Belt : host::Transmission::Leadscrew;
    m.pulley_teeth = static_cast<int>(
        r.get_int(p + "pulley_teeth", m.pulley_teeth, 1, 1000, "pulley teeth (belt; seed 000: GT2 20T)"));
    m.belt_pitch_mm = r.get_float(p + "belt_pitch_mm", m.belt_pitch_mm, 0.001, 100.0, "belt pitch, mm (GT2: 2.0)");
    m.lead_mm = r.get_float(p + "lead_mm", m.lead_mm, 0.001, 1000.0, "leadscrew pitch per start, mm");
    m.screw_starts = static_cast<int>(r.get_int(p + "screw_starts", m.screw_starts, 1, 16, "leadscrew starts"));
    m.gear_ratio =
        r.get_float(p + "gear_ratio", m.gear_ratio, 0.001, 1000.0, "motor revolutions per pulley/screw revolution");
    const double calibrated = r.get_float(
        p + "steps_per_mm", 0.0, 0.0, 1e6,
        "calibrated microsteps per mm at " + p +
            "microsteps (full steps per mm = steps_per_mm / microsteps; grbl's $100), instead of the motor and "
            "transmission keys above (given with them, it must equal their value)" +
            // Z has no motor model (no architecture has Z STEP pins): its microstep mode changes nothing.
            (axis == "z" ? std::string()
                         : "; with mechanics.model = \"dynamic\" it needs " + p +
                               "microsteps (or those keys) beside it, else it is refused") +
            "; 0: computed from them");
    if (calibrated > 0.0) m.calibrated_steps_per_mm = calibrated;
    read_axis_limits(r, axis, m.limits);
    m.travel_mm = r.get_float(p + "travel_mm", m.travel_mm, 0.0, 1e6, "axis travel, mm (0 = unlimited)");
    check_calibration(r, p, m);
    try {
        host::validate(m, r.has(p + "microsteps") ? p + "microsteps" : p.substr(0, p.size() - 1));
    } catch (const BadInput& e) {
        r.fail(p.substr(0, p.size() - 1), e.what());
    }
}

// The job starts where the scenario puts the tool: within the soft limits too.
void check_start(const KeyReader& r, geom::Vec2 start_mm, const host::MachineModel& machine) {
    using host::MachineAxis;
    if (const auto why = soft_limit_breach(machine, MachineAxis::X, start_mm.x_mm, start_mm.x_mm)) {
        r.fail("scenario.start_x_mm", *why);
    }
    if (const auto why = soft_limit_breach(machine, MachineAxis::Y, start_mm.y_mm, start_mm.y_mm)) {
        r.fail("scenario.start_y_mm", *why);
    }
}

// Which pins the VCD holds, and when: a window of a long job keeps the file to the part of interest.
// A fault on a link the architecture does not have would change nothing: refused, so that a study never reads
// a clean run as a faulty one.
void check_fault_links(const KeyReader& r, const FaultSettings& f, const Architecture& a) {
    if (f.uart.any() && !a.fault_links().uart) {
        r.fail(f.uart.ber > 0.0 ? "faults.uart_ber" : "faults.uart_frame_loss_rate",
               "the " + a.name() + " architecture has no UART link the faults can act on");
    }
    if (f.spi_ber > 0.0 && !a.fault_links().spi) {
        r.fail("faults.spi_ber", "the " + a.name() + " architecture has no SPI link");
    }
    if (f.usb_spikes.any() && !a.fault_links().usb) {
        r.fail("faults.usb_spike_rate", "the " + a.name() + " architecture has no USB serial link");
    }
    if (f.host_stall.any() && !a.fault_links().host) {
        r.fail("faults.host_stall_s", "the " + a.name() + " architecture has no host program model that can stall");
    }
    if (f.step_loss_rate > 0.0 && !a.fault_links().step_input) {
        r.fail("faults.step_loss_rate", "the " + a.name() + " architecture drives no DRV8825");
    }
}

// A study in one file: the variants are checked when the scenario is read, so that a bad one is named with its
// line by `run` too, not only by the compare that would use it.
void read_compare_variants(KeyReader& r, Scenario& s) {
    const std::vector<std::string> texts = r.get_string_list(
        "compare.variants",
        std::string("the variants `cncsim compare` runs this scenario as when no --variant is given, a column each "
                    "(docs/compare.md, Variants), each ") +
            kVariantSyntax + "; []: none, the architectures are compared");
    for (const std::string& t : texts) s.compare_variants.push_back(parse_variant(t, r.where("compare.variants")));
    check_variant_names(s.compare_variants, r.where("compare.variants"));
}

void read_trace_window(KeyReader& r, Scenario& s) {
    s.trace_signals = r.get_string_list(
        "trace.signals",
        "pins and signals the VCD holds, by name or as BLOCK.NAME (docs/vcd.md: the pins of each architecture "
        "by block, and the real-valued carriage_x_mm, carriage_y_mm); an unknown name is refused with the allowed "
        "ones; []: all of "
        "them except the SPI wires sclk, mosi, miso and ss, which are driven bit by bit only when named here (or "
        "with spi.trace_wires = true)");
    constexpr double kMaxTraceS = 1e6;  // the largest scenario.max_sim_s
    const double from_s = r.get_float("trace.from_s", 0.0, 0.0, kMaxTraceS,
                                      "start of the VCD's window, s of simulated time: the file holds the levels at "
                                      "that time, then the changes until trace.to_s");
    const double to_s = r.get_float("trace.to_s", 0.0, 0.0, kMaxTraceS,
                                    "end of the VCD's window, s of simulated time, > trace.from_s; 0: the end of "
                                    "the run");
    if (to_s > 0.0 && !(to_s > from_s)) {
        r.fail("trace.to_s", fmt::format(FMT_STRING("{:g} s must be after trace.from_s = {:g} s"), to_s, from_s));
    }
    s.trace_from_ps = s_to_ps(from_s);
    if (to_s > 0.0) s.trace_to_ps = s_to_ps(to_s);
}

// Keys an earlier cncsim read, now a machine key that every architecture takes: refused with the new name, so that
// an old scenario does not silently run with the default.
void reject_moved_keys(const KeyReader& r) {
    std::vector<std::pair<std::string, std::string>> moved = {
        {"host.rapid_feed_mm_per_min", "machine.rapid_feed_mm_per_min (mm/min)"},
        {"planner.rapid_velocity_mm_per_s", "machine.rapid_feed_mm_per_min (mm/min: 60 x the mm/s value)"}};
    for (const char* axis : {"x", "y"}) {
        for (const char* limit : {"max_velocity_mm_per_s", "max_accel_mm_per_s2", "max_jerk_mm_per_s3"}) {
            moved.emplace_back(std::string("planner.") + axis + "." + limit,
                               std::string("machine.") + axis + "." + limit);
        }
    }
    for (const auto& [old_key, new_key] : moved) {
        if (r.has(old_key)) {
            r.fail(old_key, "replaced by " + new_key +
                                ": one machine for every architecture "
                                "(docs/scenario-reference.md, \"Which keys apply to which architecture\")");
        }
    }
}
}  // namespace

namespace {

// Reads every key (registering its documentation); `base` resolves relative paths.
Scenario read(KeyReader& r, const std::string& file, const fs::path& base) {
    reject_moved_keys(r);
    Scenario s;
    s.file = file;
    s.name = r.get_string("scenario.name", fs::path(file).stem().string(), "name shown in reports");
    s.architecture = r.get_choice("scenario.architecture", architecture_names().front(), architecture_names(),
                                  "controller architecture (docs/architectures.md)");
    const std::string job = r.get_string("scenario.job", "",
                                         "job file, relative to the scenario: G-code, a seed 000 steps file, or a DXF "
                                         "drawing that the CAM turns into G-code first ([cam], docs/cam.md)");
    const std::string tool_table = r.get_string(
        "scenario.tool_table", "",
        "LinuxCNC tool-table file, relative to the scenario (lines `T1 P1 D3.0 Z+0.5 ;comment`: tool, pocket, "
        "diameter and Z length offset in mm): with it the job's T, M6, M61, G43/G43.1/G43.2/G49 (H) and "
        "G40/G41/G42/G41.1/G42.1 (D) are executed as LinuxCNC does (docs/gcode.md); empty: none, and those words "
        "are ignored");
    r.get_string("scenario.machine", "", kMachineDoc);  // its tables joined the document before this reading
    const std::string format =
        r.get_choice("scenario.job_format", "auto", {"auto", "gcode", "steps", "drawing"},
                     "job format; auto: .steps and .csv are steps files, .dxf a drawing, the rest G-code");
    s.seed = static_cast<std::uint64_t>(r.get_int("scenario.seed", 1, 0, INT64_MAX, "seed of every random source"));
    const double max_sim_s = r.get_float(
        "scenario.max_sim_s", 0.0, 0.0, 1e6,
        "simulated-time limit, s: a run that needs longer fails; 0: from the job, 2 x its estimate + 1 s per "
        "programmed move + 10 s (estimate: host start-up and link time plus every move's length at its feed, "
        "held to what the axes can do; run/job_estimate.hpp)");
    if (max_sim_s > 0.0) s.max_sim_s = max_sim_s;
    s.interpreter.policy =
        r.get_choice("scenario.gcode_policy", "lenient", {"lenient", "strict"},
                     "lenient: run what the machine can do and list the words it ignores; strict: every word the "
                     "machine does not execute is an error (docs/gcode.md)") == "strict"
            ? host::GcodePolicy::Strict
            : host::GcodePolicy::Lenient;
    s.interpreter.start_mm.x_mm = r.get_float("scenario.start_x_mm", 0.0, -1e6, 1e6, "tool X at job start, mm");
    s.interpreter.start_mm.y_mm = r.get_float("scenario.start_y_mm", 0.0, -1e6, 1e6, "tool Y at job start, mm");
    s.interpreter.feed_mm_per_min = r.get_optional_float(
        "scenario.feed_mm_per_min", 1e-3, 1e6, "the job's own F",
        "every F word of a G-code job read as this feed, mm/min, whatever its unit (a feed study without editing the "
        "job; an inverse-time F under G93 is kept)");

    read_axis(r, "x", s.machine.x);
    read_axis(r, "y", s.machine.y);
    read_axis(r, "z", s.machine.z);
    s.interpreter.z_max_feed_mm_per_min = s.machine.z.limits.max_velocity_mm_per_s * 60.0;
    s.machine.soft_limits = r.get_bool("machine.soft_limits", s.machine.soft_limits,
                                       "refuse a G-code job or start position that leaves [0, travel_mm] on an axis "
                                       "with a travel (grbl $20); false: no check");
    // One rapid speed, as LinuxCNC has one traverse limit over its per-axis MAX_VELOCITY (grbl's rapids run at the
    // axis max rates: a value at or above the axis limits gives that).
    s.interpreter.rapid_feed_mm_per_min = r.get_float(
        "machine.rapid_feed_mm_per_min", s.interpreter.rapid_feed_mm_per_min, 1.0, 65535.0,
        "G0 speed, mm/min, of every architecture (seed 000 test log: 1200), held to the axis velocity limits: "
        "the seed 000 G0 packet feed, each axis's speed in a seed 003 G00 (its dog-leg), the trajectory planner's "
        "G0 path speed");
    check_start(r, s.interpreter.start_mm, s.machine);

    s.driver.strict = r.get_bool("driver.strict", s.driver.strict,
                                 "DRV8825 drops STEP pulses that break tWH/tWL (false: counts every rising edge)");
    read_mechanics_settings(r, s.mechanics);
    if (s.mechanics.model == MechanicsModel::Dynamic) {
        check_full_steps(r, "machine.x.", s.machine.x);
        check_full_steps(r, "machine.y.", s.machine.y);
    }

    s.interpreter.operator_pause_s =
        r.get_float("host.operator_pause_s", s.interpreter.operator_pause_s, 0.0, 1e6,
                    "time an operator takes to resume after M0/M1/M60 (the job pauses that long), s");
    s.interpreter.feed_unit = r.get_choice("host.feed_unit", "mm/min", {"mm/min", "mm/s"},
                                           "unit of F in the job (seed 003 used mm/s)") == "mm/min"
                                  ? host::FeedUnit::MmPerMinute
                                  : host::FeedUnit::MmPerSecond;
    read_cam_settings(r, s.cam);
    s.cam.options.gcode.feed_in_mm_per_s = s.interpreter.feed_unit == host::FeedUnit::MmPerSecond;
    s.cam.options.ordering.start_mm = s.interpreter.start_mm;

    read_fault_settings(r, s.seed, s.faults);
    read_events(r, s.events);
    for (const Architecture* a : architectures()) {
        std::shared_ptr<const ArchSettings> settings = a->read_settings(r, s, base);
        if (a->name() == s.architecture) {
            s.arch_settings = std::move(settings);
            check_fault_links(r, s.faults, *a);
            a->check_events(r, s.events, *s.arch_settings);
        }
    }

    s.vcd_path = r.get_string("trace.vcd", "",
                              "VCD file to write (relative to the working directory), with its gtkwave save file "
                              "beside it (FILE.vcd -> FILE.gtkw); empty: none");
    std::vector<std::string> timescales = metrics::vcd_timescale_names();
    timescales.insert(timescales.begin(), "auto");
    const std::string timescale = r.get_choice(
        "trace.timescale", "auto", timescales,
        "VCD time unit; auto: 100 ps, which keeps every edge of an ideal FPGA (20 ns) and AVR (62.5 ns) clock exact, "
        "or 1 ps when a clock's offset or jitter (docs/metrics.md, Clocks) puts its edges between; a unit that "
        "would round a clocked edge is refused; pins timed otherwise (CP2102, SPI master) are written at the "
        "nearest tick");
    if (timescale != "auto") s.vcd_timescale_fs = *metrics::parse_vcd_timescale_fs(timescale);
    read_trace_window(r, s);
    read_compare_variants(r, s);
    s.report_path = r.get_string("trace.report", "", "JSON report to write; empty: none");
    s.detail = r.get_bool("trace.detail", false,
                          "the JSON report also holds the logs that grow with steps, servo periods and packets "
                          "(pulse runs, rate and velocity logs, packets, dead-time gaps); false: per-move records "
                          "and summaries");

    if (!tool_table.empty()) {
        const std::string path = (base / tool_table).lexically_normal().string();
        if (!fs::is_regular_file(path)) r.fail("scenario.tool_table", "the tool table " + path + " is not a file");
        s.interpreter.tool_table = std::make_shared<const host::ToolTable>(host::ToolTable::load(path));
    }
    if (!job.empty()) {
        s.job_path = (base / job).lexically_normal().string();
        s.job_key = r.where("scenario.job");
        const std::string ext = fs::path(job).extension().string();
        const bool steps = format == "steps" || (format == "auto" && (ext == ".steps" || ext == ".csv"));
        s.job_format = steps ? JobFormat::Steps : JobFormat::GCode;
        if (format == "drawing" || (format == "auto" && is_drawing(job))) s.drawing_path = s.job_path;
        if (steps && s.interpreter.feed_mm_per_min)
            r.fail("scenario.feed_mm_per_min", "applies to a G-code job's F words; a steps file has no F");
    }
    return s;
}

}  // namespace

toml::table parse_toml(const std::string& path, const std::string& what) {
    if (fs::is_directory(path)) throw BadInput(path, "is a folder, not a " + what + " (TOML)");
    std::ifstream in(path);
    if (!in) throw BadInput(path, "cannot open the " + what);
    std::stringstream text;
    text << in.rdbuf();
    try {
        return toml::parse(text.str(), path);
    } catch (const toml::parse_error& e) {
        throw BadInput(path + ":" + std::to_string(e.source().begin.line), std::string(e.description()));
    }
}

namespace {

std::string machine_tables_text() {
    std::string text;
    for (const std::string& t : machine_tables()) text += (text.empty() ? "[" : ", [") + t + "]";
    return text;
}

// A machine file holds the machine and nothing else: the job and the controller belong to a scenario.
void check_machine_file(const toml::table& machine, const std::string& path) {
    for (const auto& [k, node] : machine) {
        const std::string key(k.str());
        if (node.is_table() && is_machine_key(key + ".")) continue;
        const int line = node.source().begin.line;
        throw BadInput(path + (line > 0 ? ":" + std::to_string(line) : "") + ": " + key,
                       "not a machine table: a machine file holds only " + machine_tables_text() +
                           " (`cncsim keys machine` lists the machine's keys); the job, the architecture and the "
                           "controller's keys go in a scenario, or on the command line (--set key=value)");
    }
}

// The machine file's keys join the scenario's, moved so that messages name the machine file and line; a key the
// scenario or --set gives wins.
void merge_missing(toml::table& into, toml::table& from) {
    for (auto&& [k, node] : from) {
        toml::node* mine = into.get(k.str());
        if (mine == nullptr) {
            into.insert(std::string(k.str()), std::move(node));
        } else if (mine->is_table() && node.is_table()) {
            merge_missing(*mine->as_table(), *node.as_table());
        }
    }
}

void include_machine_file(toml::table& root, const std::string& file, const fs::path& base,
                          const std::vector<std::string>& overridden) {
    KeyReader r(root, file, overridden);
    const std::string name = r.get_string("scenario.machine", "", kMachineDoc);
    if (name.empty()) return;
    const std::string path = (base / name).lexically_normal().string();
    std::error_code ec;
    if (!fs::exists(path, ec)) r.fail("scenario.machine", "the machine file " + path + " does not exist");
    toml::table machine = parse_toml(path, "machine file");
    check_machine_file(machine, path);
    merge_missing(root, machine);
}

bool overrides_key(const std::vector<std::string>& overrides, const std::string& key) {
    return std::any_of(overrides.begin(), overrides.end(),
                       [&](const std::string& o) { return override_key(o) == key; });
}

enum class JobNeed { Required, None };

// A TOML document read as a scenario: `file` names it in messages, `base` resolves its relative paths. Without a
// job (JobNeed::None) it describes a machine and a controller only, which nothing runs.
Scenario load_document(toml::table root, const std::string& file, const fs::path& base,
                       const std::vector<std::string>& overrides, JobNeed job = JobNeed::Required) {
    std::vector<std::string> overridden;
    for (const std::string& o : overrides) {
        apply_override(root, o);
        overridden.push_back(override_key(o));
    }
    include_machine_file(root, file, base, overridden);
    KeyReader reader(root, file, overridden);
    Scenario s = read(reader, file, base);
    reader.reject_unknown_keys();
    if (job == JobNeed::Required && s.job_path.empty() && find_architecture(s.architecture, file).job_use().runs_job) {
        reader.fail("scenario.job", "missing: the job file to run is required");
    }
    return s;
}

// A job given where a scenario belongs: how to run it instead.
void refuse_job_file(const std::string& path) {
    if (fs::is_directory(path)) return;  // named as a folder by parse_toml
    if (input_kind(path) == InputKind::Job) {
        throw BadInput(path, "is a job file, not a scenario (TOML): `cncsim run " + path +
                                 "` runs it on the default machine (--machine MACHINE.toml: on yours), `cncsim "
                                 "compare " +
                                 path +
                                 "` on every architecture; a scenario names it as scenario.job "
                                 "(`cncsim init` writes one to start from)");
    }
}

// A machine file given as a scenario (no job to run): how to run a job on it.
void refuse_machine_file(const toml::table& root, const std::string& path, const std::vector<std::string>& overrides) {
    const bool only_machine = std::all_of(root.begin(), root.end(), [](const auto& kv) {
        return kv.second.is_table() && is_machine_key(std::string(kv.first.str()) + ".");
    });
    if (root.empty() || !only_machine || overrides_key(overrides, "scenario.job")) return;
    throw BadInput(path, "holds only " + machine_tables_text() +
                             ": a machine file, not a scenario; run a job on it with `cncsim run JOB.nc --machine " +
                             path + "`, or name it as scenario.machine in a scenario");
}

// A file named on the command line: it must exist and be a file.
void check_input_file(const std::string& path, const std::string& where, const std::string& what) {
    std::error_code ec;
    if (fs::is_directory(path, ec)) throw BadInput(where, "is a folder, not a " + what);
    if (!fs::exists(path, ec)) throw BadInput(where, "no such " + what);
}

}  // namespace

const std::vector<std::string>& machine_tables() {
    static const std::vector<std::string> tables = {"machine", "driver", "motor", "mechanics"};
    return tables;
}

bool is_machine_key(const std::string& key) {
    const auto& t = machine_tables();
    return std::any_of(t.begin(), t.end(), [&](const std::string& table) { return key.rfind(table + ".", 0) == 0; });
}

InputKind input_kind(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (ext == ".toml") return InputKind::Scenario;
    for (const char* job : {".nc", ".ngc", ".gcode", ".gco", ".g", ".tap", ".cnc", ".txt", ".steps", ".csv", ".dxf"}) {
        if (ext == job) return InputKind::Job;
    }
    std::ifstream in(path);
    for (std::string line; std::getline(in, line);) {
        const std::size_t first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#') continue;
        if (line[first] == '[') return InputKind::Scenario;
        const std::size_t eq = line.find('=');
        const bool key = eq != std::string::npos && eq > first &&
                         line.find_first_not_of(
                             "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_-.\"' \t", first) == eq;
        return key ? InputKind::Scenario : InputKind::Job;
    }
    return InputKind::Scenario;
}

Scenario load_scenario(const std::string& path, const std::vector<std::string>& overrides) {
    refuse_job_file(path);
    toml::table root = parse_toml(path, "scenario file");
    refuse_machine_file(root, path, overrides);
    return load_document(std::move(root), path, fs::path(path).parent_path(), overrides);
}

Scenario load_job_run(const JobRun& run, const std::vector<std::string>& overrides) {
    check_input_file(run.job, run.job, "job file");
    if (!run.machine.empty()) check_input_file(run.machine, "--machine " + run.machine, "machine file");
    toml::table scenario{{"job", run.job}, {"name", fs::path(run.job).stem().string()}};
    if (!run.machine.empty()) scenario.insert("machine", run.machine);
    if (!run.architecture.empty()) scenario.insert("architecture", run.architecture);
    toml::table root{{"scenario", std::move(scenario)}};
    Scenario s = load_document(std::move(root), run.machine.empty() ? run.job : run.machine, fs::path(), overrides);
    if (!overrides_key(overrides, "scenario.job")) s.job_key = run.job;
    if (!find_architecture(s.architecture, s.file).job_use().runs_job) {
        throw BadInput(overrides_key(overrides, "scenario.architecture") ? "--set scenario.architecture"
                                                                         : "--arch " + s.architecture,
                       s.architecture + " runs no job: it takes a scenario of its own (docs/architectures.md)");
    }
    return s;
}

Scenario load_machine(const std::string& machine, const std::vector<std::string>& overrides) {
    check_input_file(machine, "--machine " + machine, "machine file");
    toml::table root{{"scenario", toml::table{{"machine", machine}}}};
    return load_document(std::move(root), machine, fs::path(), overrides, JobNeed::None);
}

std::vector<KeyDoc> scenario_keys() {
    const toml::table empty;
    KeyReader reader(empty, "defaults");
    read(reader, "<scenario file name>", fs::path("."));
    return reader.docs();
}

}  // namespace cnc::sim
