// The controller architectures, one entry each (docs/architectures.md): the scenario reader, the run and the
// compare command take the list from here, so that a new architecture is added in architecture.cpp alone.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "run/arch_run.hpp"
#include "run/program_report.hpp"

namespace cnc::sim {

class KeyReader;
struct Scenario;
struct Job;

struct Architecture {
    const char* name;  // the value of scenario.architecture and the key of its section in the report
    // Reads the architecture's own scenario keys (registering their documentation); every entry's reader runs for
    // every scenario, so that `cncsim keys` lists them all and a misspelt key is refused whatever the architecture.
    void (*read_settings)(KeyReader& r, Scenario& s, const std::filesystem::path& base);
    // Elaborates the system, simulates it and measures: the traces for the metrics and its report section.
    ArchRun (*run)(const Scenario& s, const Job& job);
    bool runs_job;  // the host runs scenario.job (G-code or steps file); false: the architecture scripts itself
    LaserSwitching laser_switching;  // how the job's laser words reach the head (program warnings)
    // The run reads a G-code job's moves from the file again as it runs (Job::program keeps no moves).
    bool streams_job;
};

[[nodiscard]] const std::vector<Architecture>& architectures();
[[nodiscard]] std::vector<std::string> architecture_names();
// "fpga-uart, atmega, ..." for messages.
[[nodiscard]] std::string architecture_list();
// BadInput at `where` naming the allowed architectures when `name` is not one of them.
[[nodiscard]] const Architecture& find_architecture(const std::string& name, const std::string& where);

}  // namespace cnc::sim
