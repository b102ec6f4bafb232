// The gtkwave save file written beside every VCD (docs/vcd.md "gtkwave"), so that `gtkwave FILE.vcd FILE.gtkw`
// opens on the traced signals instead of an empty wave pane: one group per hardware block in the VCD's order, the
// real variables (the carriage's position) as analog traces, zoomed to the job's first move with the marker on its
// first STEP edge. The format is gtkwave 3.3's own (what its File > Write Save File writes): "[key] value" lines,
// the "*zoom marker named-markers" line, then per trace an "@flags" line (hex, gtkwave's TraceEntFlagBits) before
// the traces it applies to.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/units.hpp"

namespace cnc::sim {

// A signal as the VCD declares it.
struct SavedSignal {
    std::string block;  // its scope under the top scope; empty: the top scope itself
    std::string name;
    bool real = false;          // a 64-bit real variable, drawn as an analog trace
    bool interpolated = false;  // real: samples of a quantity that moves between them (drawn as lines), else a value
                                // held until the next one (drawn as steps)
};

// What a run's VCD holds and over which time.
struct TraceLayout {
    std::string top_scope;
    std::vector<SavedSignal> signals;  // in the VCD's order
    std::int64_t timescale_fs = 0;     // trace.timescale
    TimePs from_ps = 0;                // the file's first and last time (trace.from_s .. trace.to_s or the run's end)
    TimePs to_ps = 0;
};

// A span of simulated time.
struct TimeSpan {
    TimePs from_ps = 0;
    TimePs to_ps = 0;
};

// The save file's path: FILE.vcd -> FILE.gtkw, any other name gets ".gtkw" appended; none when the VCD is written
// to a device or a pipe (/dev/null), which has no folder of its own to put a file beside.
[[nodiscard]] std::optional<std::string> gtkw_path(const std::string& vcd_path);

// The save file's text for the VCD at `vcd_path` (written as its absolute path, so that `gtkwave FILE.gtkw` finds
// it from any folder). The view spans `first_move` (with a twentieth of its length either side) when it lies in the
// file, the whole file otherwise.
[[nodiscard]] std::string gtkw_text(const std::string& vcd_path, const TraceLayout& layout,
                                    const std::optional<TimeSpan>& first_move);

}  // namespace cnc::sim
