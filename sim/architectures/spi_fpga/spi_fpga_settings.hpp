// Scenario keys of the spi-fpga architecture (seed 004), read into one struct by read_spi_fpga_settings():
// [planner] the trajectory planner (planner/planner_settings.hpp), host.* the servo thread (beside the seed 000
// sender's host.* keys), [spi] the link, [fpga_spi] the FPGA design (its own table: the fpga.* keys belong to the
// seed 000 FPGA).
#pragma once
#include <filesystem>
#include <string>

#include "architectures/architecture.hpp"
#include "architectures/oscillator/oscillator_settings.hpp"
#include "architectures/rtl/rtl_settings.hpp"
#include "fpga/spi/core/spi_fpga_config.hpp"
#include "host/core/machine.hpp"
#include "host/core/planner/planner_config.hpp"
#include "host/servo/core/servo_config.hpp"
#include "scenario/key_reader.hpp"
#include "spi/core/spi_timing.hpp"

namespace cnc::sim {

struct SpiFpgaSettings final : ArchSettings {
    host::planner::PlannerConfig planner;
    // Period, latency and law settings; the system fills in the machine (axes, origin) and the FPGA clock.
    host::servo::ServoConfig servo;
    // trace_wires is the spi.trace_wires key; the system also drives the wires when trace.signals names one.
    spi::SpiConfig link;
    fpga::SpiFpgaConfig fpga;
    OscillatorSettings clock;  // the FPGA board's oscillator
    RtlSettings rtl;           // the FPGA as event-driven blocks or as Verilog in the loop (drives the SPI wires)
};

// Reads and validates the keys (registering their documentation). BadInput naming the key for an axis limit of 0,
// a servo period shorter than the SPI transfer slot, a latency bound that leaves no room for the transfer in the
// period, and a link the FPGA's oversampling slave cannot follow. The step-rate limit needs the machine's steps/mm:
// check_rate_limits() does it. Verilog paths are resolved against the scenario's folder `base`.
void read_spi_fpga_settings(KeyReader& r, const std::filesystem::path& base, SpiFpgaSettings& settings,
                            const host::MachineModel& machine);

// BadInput ("<file>: planner.<axis>.max_velocity_mm_per_s") when an axis's stepgen velocity limit (the planner's
// times 1 + host.stepgen_margin) needs a rate word period below the FPGA's shortest STEP period.
void check_rate_limits(const SpiFpgaSettings& settings, const host::MachineModel& machine, const std::string& file);

}  // namespace cnc::sim
