// Which of an architecture's traceable signals a scenario's VCD holds (trace.signals), shared by the SystemC
// trace (vcd_trace.hpp) and the lock-stepped lathe rig's pin trace.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "scenario/scenario.hpp"

namespace cnc::sim {

// A signal the file can hold, wire or real, by name (unique in the file) and the hardware block it belongs to
// (its scope in the VCD).
struct TraceCandidate {
    std::string name;
    bool on_request = false;  // held only when trace.signals names it
    std::string block;
};

// Whether `requested` (a trace.signals entry: NAME or BLOCK.NAME) names the signal `name` of `block`.
[[nodiscard]] bool names_signal(const std::string& requested, const std::string& block, const std::string& name);

// The signals of the file (indices into `all`): those trace.signals names (as NAME or BLOCK.NAME), in the order
// the architecture lists them, or every one that is not on request. BadInput naming trace.signals for an unknown
// or repeated name.
[[nodiscard]] std::vector<std::size_t> select_traced(const Scenario& s, const std::vector<TraceCandidate>& all);

}  // namespace cnc::sim
