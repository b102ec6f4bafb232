// The keys of running an FPGA's Verilog in the loop: fpga.model, shared by both FPGA architectures (so that a
// compare of them switches both), and the design keys under each FPGA's own table: <prefix>.rtl_top,
// <prefix>.rtl_sources, <prefix>.rtl_parameters (prefix "fpga" for seed 000, "fpga_spi" for seed 004).
#pragma once
#include <filesystem>
#include <string>

#include "rtl/plugin_spec.hpp"
#include "scenario/key_reader.hpp"

namespace cnc::sim {

struct RtlSettings {
    bool rtl = false;  // fpga.model = "rtl": the Verilog verilated in the loop; false: the event-driven model
    rtl::Design design;
};

// Paths resolved against the scenario's folder `base`. BadInput naming the key: a design key without
// fpga.model = "rtl", a parameter not NAME=VALUE, a file that is not there, or RTL asked of a cncsim built without
// Verilator.
void read_rtl_settings(KeyReader& r, const std::filesystem::path& base, const std::string& prefix, RtlSettings& s);

}  // namespace cnc::sim
