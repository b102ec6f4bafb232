// The run's VCD file, written as the simulation runs (nothing is kept in memory): the traced pins by their names
// (unique in the file), each in the scope of the hardware block it belongs to (docs/vcd.md "Scopes"), at
// trace.timescale, the pins trace.signals names (by default every pin but those traced only on request) and the
// carriage's real-valued positions (TracedReal), in the window trace.from_s .. trace.to_s. Edges of pins timed by a
// clock with a whole-ps period (FPGA 50 MHz, AVR 16 MHz) are exact, and a timescale that would round them is
// refused; the others are written at the nearest tick (metrics/vcd/vcd_writer.hpp). The file is an OutputFile:
// complete, or not there.
#pragma once
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include <systemc>

#include "metrics/vcd/vcd_writer.hpp"
#include "output/gtkw_save.hpp"
#include "output/output_file.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim {

struct TracedPin {
    const sc_core::sc_signal<bool>* signal;  // traced under its basename
    const char* block;                       // the hardware block whose pin it is: driver_x, link, fpga, ...
    std::optional<std::int64_t> clock_hz;    // the clock that times its edges; nullopt: host timing or constant
    bool on_request = false;                 // in the VCD only when trace.signals names it
};

struct TracedReal {
    // Traced under its basename as a 64-bit real variable (the carriage's position: mechanics/carriage.hpp).
    const sc_core::sc_signal<double, sc_core::SC_MANY_WRITERS>* signal;
    const char* block;
    bool sampled = false;  // samples of a quantity that moves between them (dynamic mechanics), not a held value
};

// Whether the scenario writes a VCD that trace.signals asks to hold one of `names` of `block`.
[[nodiscard]] bool trace_names_any(const Scenario& s, const char* block, std::initializer_list<const char*> names);

class VcdTrace {
public:
    // Call during elaboration, after the pins are bound: their current values are the initial ones. Throws
    // BadInput naming trace.signals for a name that is not one of `pins` or `reals`, trace.timescale for a
    // timescale that would round a clocked pin's edges, the file when it cannot be written.
    VcdTrace(const Scenario& s, const std::vector<TracedPin>& pins, const std::vector<TracedReal>& reals);
    VcdTrace(const VcdTrace&) = delete;
    VcdTrace& operator=(const VcdTrace&) = delete;

    // Ends the file at the current simulation time (or trace.to_s); OutputError if it could not be written.
    void close();
    // What the file holds, for its gtkwave save file; its end once closed.
    [[nodiscard]] const TraceLayout& layout() const { return m_layout; }

private:
    // Writes one change through `write` (a wire's level or a real's value), or keeps it as the value at the
    // window's start through `keep` while the window has not begun.
    template <typename Write, typename Keep>
    void change(Write write, Keep keep);
    void open_at(TimePs t_ps);

    std::optional<OutputFile> m_file;  // opened once the pins and the timescale are accepted
    std::int64_t m_timescale_fs;
    std::string m_timescale_key;
    std::vector<metrics::VcdSignal> m_signals;  // the levels before the window, then the initial levels
    TimePs m_from_ps;
    std::optional<TimePs> m_to_ps;
    std::optional<metrics::VcdWriter> m_writer;
    bool m_ended = false;
    TraceLayout m_layout;
};

}  // namespace cnc::sim
