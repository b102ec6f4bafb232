// A scenario: one job on one machine through one controller architecture, with every model parameter. Loaded from
// TOML, overridden by --set, validated in one place: the keys every architecture shares here (scenario.cpp), each
// architecture's own keys in its folder (architectures/<name>/), kept for the chosen one (Scenario::settings).
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "architectures/architecture.hpp"
#include "common/geometry.hpp"
#include "common/units.hpp"
#include "host/core/gcode.hpp"
#include "host/core/machine.hpp"
#include "mechanics/core/drv8825_config.hpp"
#include "run/progress.hpp"
#include "scenario/cam_settings.hpp"
#include "scenario/event_settings.hpp"
#include "scenario/fault_settings.hpp"
#include "scenario/key_reader.hpp"
#include "scenario/mechanics_settings.hpp"
#include "scenario/variant.hpp"

namespace cnc::sim {

enum class JobFormat { GCode, Steps };

struct Scenario {
    std::string file;  // the scenario file as given
    std::string name;
    std::string architecture;  // scenario.architecture (architectures/registry.hpp)
    std::string job_path;      // resolved against the scenario's folder
    std::string job_key;       // where scenario.job was set ("s.toml:3: scenario.job", "--set scenario.job")
    JobFormat job_format = JobFormat::GCode;
    // A DXF job (scenario.job_format, docs/cam.md): the drawing; job_path names it until write_drawing_job
    // (drawing_job.hpp) names its G-code instead.
    std::string drawing_path;
    CamSettings cam;
    std::uint64_t seed = 1;
    std::optional<double> max_sim_s;  // set by the scenario; else the job's own limit (run/job_estimate.hpp)

    host::MachineModel machine;
    host::InterpreterOptions interpreter;
    mech::Drv8825Config driver;
    MechanicsSettings mechanics;
    FaultSettings faults;
    std::vector<ScenarioEvent> events;  // [[events]], in time order
    // The chosen architecture's own keys, read by its Architecture::read_settings.
    std::shared_ptr<const ArchSettings> arch_settings;

    std::string vcd_path;                          // empty: no VCD
    std::optional<std::int64_t> vcd_timescale_fs;  // trace.timescale; empty: "auto"
    std::vector<std::string> trace_signals;        // trace.signals; empty: every pin not traced on request only
    TimePs trace_from_ps = 0;                      // trace.from_s
    std::optional<TimePs> trace_to_ps;             // trace.to_s; none: the end of the run
    std::string report_path;                       // empty: no JSON file
    bool detail = false;  // the report also holds the logs that grow with steps, periods and packets
    // compare.variants: the columns `cncsim compare` makes of this scenario when no --variant is given (a run
    // reads them only to check them).
    std::vector<Variant> compare_variants;
    ProgressStyle progress = ProgressStyle::Off;  // set by the CLI from stderr, not a scenario key
    // Set by the CLI for --plots, --plot-data and --samples, which read every edge and tool sample after the run:
    // the logs are then kept whole instead of being dropped as the metrics stream (docs/streaming.md).
    bool keep_run_input = false;

    // The chosen architecture's settings as its own type (std::bad_cast for another architecture's).
    template <typename Settings>
    [[nodiscard]] const Settings& settings() const {
        return dynamic_cast<const Settings&>(*arch_settings);
    }
};

// Reads and validates; throws BadInput naming the file, line and key. A G-code job or a machine file given as a
// scenario is refused with what to do instead.
Scenario load_scenario(const std::string& path, const std::vector<std::string>& overrides);

// A TOML file parsed: BadInput naming the file (and the line of a syntax error), or that it is a folder or cannot be
// opened, calling it a `what` ("scenario", "machine file").
toml::table parse_toml(const std::string& path, const std::string& what);

// A job run without a scenario (`cncsim run JOB.nc`): the job on a machine file, or on the default machine (every
// key's default: the seed 000 machine), through one architecture. Paths are relative to the working folder.
struct JobRun {
    std::string job;
    std::string machine;       // a machine file; empty: the default machine
    std::string architecture;  // empty: the default architecture
};
// Reads it as the scenario {scenario.job = job, scenario.machine = machine, scenario.architecture}, then the
// overrides: the same keys, checks and messages as a scenario.
Scenario load_job_run(const JobRun& run, const std::vector<std::string>& overrides);

// A machine file alone (`cncsim motor-curve --machine`): read as the scenario {scenario.machine = machine}, then
// the overrides, with the same checks and messages; no job is read or needed.
Scenario load_machine(const std::string& machine, const std::vector<std::string>& overrides);

// The tables a machine file holds (scenario.machine, --machine): the machine every architecture drives.
const std::vector<std::string>& machine_tables();
[[nodiscard]] bool is_machine_key(const std::string& key);

// What `cncsim run FILE` takes FILE for. By its extension: .toml a scenario; .nc, .ngc, .gcode, .gco, .g, .tap,
// .cnc, .txt, .steps, .csv and .dxf a job. Otherwise by its first line that is neither blank nor a TOML comment: a
// table header ([...]) or a key = value assignment is a scenario, anything else (G-code) a job. A file that
// cannot be read is a scenario, so that its message names it as one.
enum class InputKind { Scenario, Job };
InputKind input_kind(const std::string& path);

// Every scenario key with its type, default, range and meaning, in reading order.
std::vector<KeyDoc> scenario_keys();

}  // namespace cnc::sim
