// The part of a PluginSpec that a scenario's Design decides, shared by both FPGA architectures: which Verilog (the
// architecture's own or the user's top with its sources) and which top parameters.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "rtl/plugin_spec.hpp"

namespace cnc::rtl {

// Sets spec's top module, sources and parameters: with no top file, `own_top` from `own_dir`'s `own_files`, else the
// user's top (the module named as the file) and sources. `from_keys` (the parameters the FPGA's scenario keys set)
// come first, those of them a user's top does not declare left out (Verilator's -G refuses them), then the
// design's own overrides.
void set_design(PluginSpec& spec, const Design& design, const std::string& own_top, const std::string& own_dir,
                const std::vector<std::string>& own_files, std::vector<std::pair<std::string, std::string>> from_keys);

}  // namespace cnc::rtl
