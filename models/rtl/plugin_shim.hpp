// The C++ side of a plug-in, written for one design: it implements rtl_model.hpp over the Verilator model class
// `prefix`, reading the ports by name and the observed nets through the model's root (Verilator's public_flat_rd).
#pragma once
#include <string>
#include <vector>

#include "rtl/plugin_spec.hpp"

namespace cnc::rtl {

// Verilator's name of a net in the model's root: the top module's name, then the instance path, "__DOT__" between.
[[nodiscard]] std::string root_member(const std::string& top_module, const ObservedNet& net);

// The shim's source. `present`: per spec.observed, whether the design has the net; `inputs_present`: per
// spec.inputs, whether the design has the port (an optional one); the absent ones are skipped.
[[nodiscard]] std::string shim_source(const PluginSpec& spec, const std::string& prefix,
                                      const std::vector<bool>& present, const std::vector<bool>& inputs_present);

// Verilator's configuration file making the observed nets readable from the root.
[[nodiscard]] std::string public_nets_config(const PluginSpec& spec);

}  // namespace cnc::rtl
