// Value Change Dump reading and writing for the subset that SystemC (sc_trace), gtkwave, Icarus and
// logic-analyser exports produce, limited to what the metrics need: 1-bit signals as edge logs.
#pragma once
#include <iosfwd>
#include <map>
#include <string>
#include <vector>

#include "common/edge_log.hpp"
#include "common/units.hpp"

namespace cnc::metrics {

// Every 1-bit variable as an edge log with exact integer ps times. Keys (and EdgeLog::name) are the leaf
// name when it is unique among the 1-bit variables, else the dotted scope path ("SystemC.top.step_x").
// A bit-select reference keeps its index ("data[3]"). x and z read as 0. Multi-bit and real variables
// are parsed and ignored. The initial level of a variable is its value in $dumpvars, or its first value
// if that comes at the first timestamp of the file (logic-analyser exports without $dumpvars); a
// variable first seen later starts at 0. Values inside $dumpoff are ignored.
// Malformed content throws cnc::BadInput("<filename>:<line>", ...).
[[nodiscard]] std::map<std::string, EdgeLog> read_vcd(std::istream& in, const std::string& filename);

// Writes the logs as 1-bit wires in one scope "cncsim". `timescale_ps` must be 1, 10 or 100 times a
// unit (ps .. s) and every edge time a multiple of it; names must be unique and contain no white space.
// Otherwise throws cnc::BadInput("write_vcd", ...).
void write_vcd(std::ostream& out, const std::vector<EdgeLog>& logs, TimePs timescale_ps = 1000);

}  // namespace cnc::metrics
