// The C++ side of a plug-in, written for one design: it implements rtl_model.hpp over the Verilator model class
// `prefix`, reading the ports by name and the observed nets through the model's root (Verilator's public_flat_rd).
#pragma once
#include <string>
#include <vector>

#include "rtl/plugin_spec.hpp"

namespace cnc::rtl {

// Verilator's name of a net in the model's root: the top module's name, then the instance path, "__DOT__" between.
[[nodiscard]] std::string root_member(const std::string& top_module, const ObservedNet& net);

// Whether Verilator's model of a design reacts to the rising edge of `clock` alone: one trigger, that edge, and no
// logic of the inputs outside clocked blocks (read off Verilator 5's root header and its generated sources). Then the
// falling edge needs no evaluation, a third of a clock period's cost; anything else (a negedge block, the clock in
// logic, another Verilator's code) is false, and each edge is evaluated both ways.
[[nodiscard]] bool rising_edge_only(const std::string& root_header, const std::string& sources,
                                    const std::string& prefix, const std::string& clock);

// The shim's source. `present`: per spec.observed, whether the design has the net; `inputs_present`: per
// spec.inputs, whether the design has the port (an optional one); the absent ones are skipped. `rising_only`:
// rising_edge_only() of the verilated design.
[[nodiscard]] std::string shim_source(const PluginSpec& spec, const std::string& prefix,
                                      const std::vector<bool>& present, const std::vector<bool>& inputs_present,
                                      bool rising_only);

// Verilator's configuration file making the observed nets readable from the root.
[[nodiscard]] std::string public_nets_config(const PluginSpec& spec);

}  // namespace cnc::rtl
