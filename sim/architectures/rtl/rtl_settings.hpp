// The keys both FPGA architectures share for running Verilog in the loop: fpga.model, fpga.rtl_top,
// fpga.rtl_sources, fpga.rtl_parameters.
#pragma once
#include <filesystem>

#include "rtl/plugin_spec.hpp"
#include "scenario/key_reader.hpp"

namespace cnc::sim {

struct RtlSettings {
    bool rtl = false;  // fpga.model = "rtl": the Verilog verilated in the loop; false: the event-driven model
    rtl::Design design;
};

// Paths resolved against the scenario's folder `base`. BadInput naming the key: an RTL key without
// fpga.model = "rtl", a parameter not NAME=VALUE, a file that is not there, or RTL asked of a cncsim built without
// Verilator.
void read_rtl_settings(KeyReader& r, const std::filesystem::path& base, RtlSettings& s);

}  // namespace cnc::sim
