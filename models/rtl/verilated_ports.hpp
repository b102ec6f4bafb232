// The ports of a verilated top as Verilator declares them in its model header (VL_IN8(&rx,0,0); VL_OUT(&q,31,0);),
// and the check of a design's ports against the list the simulation drives and reads.
#pragma once
#include <string>
#include <vector>

#include "rtl/plugin_spec.hpp"

namespace cnc::rtl {

struct VerilatedPort {
    std::string name;
    int width = 1;
    bool input = true;
};

// The ports declared in the text of a Verilator model header.
[[nodiscard]] std::vector<VerilatedPort> parse_verilated_ports(const std::string& header_text);

// BadInput naming spec.where and the port: one of the spec's ports missing (an optional input may be), of another
// width or direction, or an input the simulation does not drive. Ports the spec does not name that are outputs are
// allowed (left unread).
void check_ports(const PluginSpec& spec, const std::vector<VerilatedPort>& ports);

}  // namespace cnc::rtl
