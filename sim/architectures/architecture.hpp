// A controller architecture as the scenario reader, the job checks, `compare` and the plots know it, without
// SystemC: its name, its own scenario keys, how it takes the job, its checks of a job against the machine and its
// plot colour. What it elaborates for a run (its modules on the shared machine, the hooks the run pipeline calls:
// run/controller.hpp) is in its folder too; registry.hpp lists every architecture.
#pragma once
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "host/core/gcode.hpp"

namespace cnc::sim {

class KeyReader;
struct Scenario;
struct ScenarioEvent;

// The settings an architecture reads from its own scenario keys; the scenario keeps the chosen one's
// (Scenario::settings).
class ArchSettings {
public:
    virtual ~ArchSettings() = default;
};

// How an architecture's hardware switches the laser.
enum class LaserSwitching {
    ByMotionKind,  // on in every cutting move, off in rapids, whatever M3/M5/S say (seed 000 FPGA, seed 003 head)
    FollowsJob,    // on when the job's M3/M4 and S say so, off in rapids (seed 004's frame carries a laser bit)
};

// How an architecture takes the scenario's job.
struct JobUse {
    bool runs_job = true;           // false: it scripts itself, and scenario.job is not needed
    bool takes_steps_file = false;  // also a seed 000 steps file (packets, no programmed geometry)
    LaserSwitching laser_switching = LaserSwitching::ByMotionKind;  // the program warnings' rule
    bool streams_job = false;  // reads a G-code job's moves from the file again as it runs (Job::program
                               // then keeps none)
};

// The links of an architecture that the scenario's [faults] can disturb (scenario/fault_settings.hpp).
struct FaultLinks {
    bool uart = false;  // a UART link: faults.uart_*
    bool usb = false;   // a USB serial link (a CP2102): faults.usb_spike_*
    bool spi = false;   // an SPI link: faults.spi_ber
    bool host = false;  // a host program that can stall: faults.host_stall_*
    bool step_input = false;  // DRV8825s on the machine's pins: faults.step_loss_rate
};

// A host program on a CP2102 USB-UART link to a controller that drives DRV8825s.
[[nodiscard]] inline FaultLinks serial_host_links() {
    FaultLinks links;
    links.uart = true;
    links.usb = true;
    links.host = true;
    links.step_input = true;
    return links;
}

class Architecture {
public:
    virtual ~Architecture() = default;

    // The value of scenario.architecture, and the key of its section in the report.
    [[nodiscard]] virtual std::string name() const = 0;
    [[nodiscard]] virtual JobUse job_use() const = 0;
    // The reference the others are measured against: `compare` runs it with every comparison (for the rows that
    // measure the others over it) and shows it as a column only when asked for.
    [[nodiscard]] virtual bool baseline() const { return false; }
    // `compare` shows it unless --arch says otherwise; false for one that runs what the user gives it (a firmware),
    // which is a column only when --arch names it.
    [[nodiscard]] virtual bool compared_by_default() const { return true; }

    // Reads its own keys (registering their documentation), given the scenario's common keys read before; `base`
    // resolves relative paths. Every architecture's reader runs for every scenario, so that `cncsim keys` lists
    // every key and a misspelt key is refused whatever the architecture: only the chosen one's settings are kept.
    [[nodiscard]] virtual std::shared_ptr<const ArchSettings> read_settings(
        KeyReader& r, const Scenario& common, const std::filesystem::path& base) const = 0;

    // Before the job is read: what the machine must allow this architecture (BadInput naming the keys).
    virtual void check_machine(const Scenario& /*s*/) const {}
    // Each programmed move as the job is read, after the checks every architecture makes (run/job_limits.hpp):
    // BadInput at `where` (file:line) for what this architecture cannot run.
    virtual void check_move(const std::string& /*where*/, const host::ProgrammedMove& /*move*/,
                            const Scenario& /*s*/) const {}

    [[nodiscard]] virtual FaultLinks fault_links() const { return {}; }
    // Refuses (KeyReader::fail on the event's key) an event on an input the architecture, as `settings` make it,
    // does not have; by default it has none.
    virtual void check_events(const KeyReader& r, const std::vector<ScenarioEvent>& events,
                              const ArchSettings& settings) const;
    // Its colour in every plot ("#rrggbb"), the same in every run and comparison.
    [[nodiscard]] virtual std::string plot_colour() const = 0;
};

}  // namespace cnc::sim
