// Value Change Dump reading for what SystemC (sc_trace), gtkwave, Icarus, cncsim's own writer and logic-analyser
// exports (sigrok-cli, PulseView) produce, limited to what the metrics need: 1-bit signals as edge logs.
#pragma once
#include <iosfwd>
#include <map>
#include <string>

#include "common/edge_log.hpp"

namespace cnc::metrics {

struct VcdContents {
    // Every 1-bit variable as an edge log with integer ps times. Keys (and EdgeLog::name) are the leaf name when it
    // is unique among the 1-bit variables, else the dotted scope path ("SystemC.top.step_x"). A bit-select
    // reference keeps its index ("data[3]").
    std::map<std::string, EdgeLog> signals;
    // Every 1-bit variable's dotted scope path ("cncsim.driver_x.step_x") -> its key in `signals`.
    std::map<std::string, std::string> paths;
    // Every other variable (not read), by leaf name and by dotted path: what it is ("32 bits wide (wire)").
    std::map<std::string, std::string> other_variables;
};

// x and z read as 0. The initial level of a variable is its value in $dumpvars, or its first value if that comes
// at the first timestamp of the file (logic-analyser exports without $dumpvars); a variable first seen later
// starts at 0. Values inside $dumpoff are ignored. Times of a timescale finer than 1 ps (fs) are rounded to the
// nearest ps. Header lines "META key: value" (sigrok-cli's -O vcd puts one before $date) are skipped.
// Malformed content throws cnc::BadInput("<filename>:<line>", ...).
[[nodiscard]] VcdContents read_vcd(std::istream& in, const std::string& filename);

// The 1-bit signal `name` names: its key in `signals`, else the one signal whose dotted path ends with `name` at a
// scope boundary ("driver_x.step_x" names cncsim.driver_x.step_x); nullptr when none does, or more than one.
[[nodiscard]] const EdgeLog* find_vcd_signal(const VcdContents& vcd, const std::string& name);

}  // namespace cnc::metrics
