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
#include "scenario/key_reader.hpp"
#include "scenario/mechanics_settings.hpp"

namespace cnc::sim {

enum class JobFormat { GCode, Steps };

struct Scenario {
    std::string file;  // the scenario file as given
    std::string name;
    std::string architecture;  // scenario.architecture (architectures/registry.hpp)
    std::string job_path;      // resolved against the scenario's folder
    std::string job_key;       // where scenario.job was set ("s.toml:3: scenario.job", "--set scenario.job")
    JobFormat job_format = JobFormat::GCode;
    std::uint64_t seed = 1;
    std::optional<double> max_sim_s;  // set by the scenario; else the job's own limit (run/job_estimate.hpp)

    host::MachineModel machine;
    host::InterpreterOptions interpreter;
    mech::Drv8825Config driver;
    MechanicsSettings mechanics;
    // The chosen architecture's own keys, read by its Architecture::read_settings.
    std::shared_ptr<const ArchSettings> arch_settings;

    std::string vcd_path;                     // empty: no VCD
    std::int64_t vcd_timescale_fs = 100'000;  // trace.timescale
    std::vector<std::string> trace_signals;   // trace.signals; empty: every pin not traced on request only
    TimePs trace_from_ps = 0;                 // trace.from_s
    std::optional<TimePs> trace_to_ps;        // trace.to_s; none: the end of the run
    std::string report_path;                  // empty: no JSON file
    bool detail = false;  // the report also holds the logs that grow with steps, periods and packets
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

// Reads and validates; throws BadInput naming the file, line and key.
Scenario load_scenario(const std::string& path, const std::vector<std::string>& overrides);

// Every scenario key with its type, default, range and meaning, in reading order.
std::vector<KeyDoc> scenario_keys();

}  // namespace cnc::sim
