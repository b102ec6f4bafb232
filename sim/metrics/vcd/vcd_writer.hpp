// VCD writing, as the simulation runs (VcdWriter) or from finished edge logs (write_vcd): a top scope "cncsim"
// holding one scope per hardware block (VcdSignal::scope: driver_x, link, ...) in the order the blocks first come,
// 1-bit wires and 64-bit real variables (IEEE 1364 §18.2: "r<value> <id>", written as %.16g, what gtkwave reads;
// sigrok-cli's VCD input skips them), the initial values in $dumpvars and nothing after $enddefinitions but
// value changes and times, so that every reader (gtkwave, sigrok, PulseView) sees the whole file.
#pragma once
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "common/edge_log.hpp"
#include "common/units.hpp"

namespace cnc::metrics {

enum class VcdVarKind { Wire, Real };

struct VcdSignal {
    // Unique in the file, not only in its scope, no white space: sigrok-cli's VCD input (libsigrok 0.5.2) names its
    // channels by the variable's name alone, without the scopes.
    std::string name;
    bool initial = false;  // level at time 0 (wires)
    // The clock that times every edge of the signal. When its period is a whole number of ps (50 MHz, 16 MHz)
    // each edge is a multiple of that period and stays exact: the timescale must divide the period. Without one
    // (host software, a constant pin), or with a period that is not whole ps (the CP2102's 24 MHz: the
    // simulation itself rounds those edges to the ps), edges are written at the nearest tick.
    std::optional<std::int64_t> clock_hz;
    VcdVarKind kind = VcdVarKind::Wire;
    double initial_value = 0.0;  // value at time 0 (reals)
    std::string scope;           // the hardware block it belongs to; empty: directly in the top scope
};

// The top scope of every VCD cncsim writes.
inline constexpr const char* kVcdTopScope = "cncsim";

// The whole-ps period of a clock, if it has one.
[[nodiscard]] std::optional<TimePs> whole_period_ps(std::int64_t clock_hz);

// What VcdWriter checks before it writes: throws cnc::BadInput(where, ...) for a timescale that is not 1, 10 or
// 100 of s .. fs, a name that is empty, has white space or comes twice (in any scope), a scope with white space,
// and a timescale that does not divide the period of a signal's clock (the message gives the coarsest timescale
// that does).
void check_vcd_signals(std::int64_t timescale_fs, const std::vector<VcdSignal>& signals, const std::string& where);
// trace.timescale = "auto": 100 ps, or the coarsest finer unit that keeps every clocked edge exact (1 ps for a
// clock whose offset or jitter puts its edges on no coarser grid).
[[nodiscard]] std::int64_t auto_timescale_fs(const std::vector<VcdSignal>& signals);
// The timescale asked for, or auto_timescale_fs() when none was.
[[nodiscard]] std::int64_t chosen_timescale_fs(std::optional<std::int64_t> asked_fs,
                                               const std::vector<VcdSignal>& signals);

class VcdWriter {
public:
    // Writes the header and the initial levels, after check_vcd_signals. A capture that starts at start_ps
    // (a window of a run) gives the levels at that time, and its changes come from then on.
    VcdWriter(std::ostream& out, std::int64_t timescale_fs, std::vector<VcdSignal> signals, const std::string& where,
              TimePs start_ps = 0);

    // Signal `index` changed to `level` at t_ps; times must not decrease. std::logic_error for a time that goes
    // backwards, or an edge of a clocked signal that is not on its clock (a model that breaks its own timing).
    void change(TimePs t_ps, std::size_t index, bool level);
    // Real variable `index` took `value` at t_ps (times as for change()).
    void change_real(TimePs t_ps, std::size_t index, double value);
    // The end of the capture: a last timestamp, so that readers hold the final levels until then.
    void finish(TimePs t_ps);

private:
    void write_time(TimePs t_ps);

    std::ostream& m_out;
    std::int64_t m_timescale_fs;
    std::vector<VcdSignal> m_signals;
    std::vector<std::string> m_ids;
    TimePs m_last_ps = 0;
    std::int64_t m_written_tick = 0;
};

// The logs as a VCD (tests and tools): `timescale_fs` 1, 10 or 100 of a unit and every edge time a multiple of
// it, edges in time order. Otherwise throws cnc::BadInput("write_vcd", ...).
void write_vcd(std::ostream& out, const std::vector<EdgeLog>& logs, std::int64_t timescale_fs = 1'000'000);

}  // namespace cnc::metrics
