// The run's VCD file, written as the simulation runs (nothing is kept in memory): the traced pins by their
// machine names, at trace.timescale. Edges of pins timed by a clock with a whole-ps period (FPGA 50 MHz, AVR
// 16 MHz) are exact, and a timescale that would round them is refused; the others are written at the nearest
// tick (metrics/vcd_writer.hpp).
#pragma once
#include <cstdint>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <systemc>

#include "metrics/vcd_writer.hpp"

namespace cnc::sim {

struct TracedPin {
    const sc_core::sc_signal<bool>* signal;  // traced under its basename
    std::optional<std::int64_t> clock_hz;    // the clock that times its edges; nullopt: host timing or constant
};

class VcdTrace {
public:
    // Call during elaboration, after the pins are bound: their current levels are the initial ones. Throws
    // BadInput(timescale_key, ...) for a timescale that would round a clocked pin's edges, BadInput(path, ...)
    // when the file cannot be written.
    VcdTrace(const std::string& path, std::int64_t timescale_fs, const std::vector<TracedPin>& pins,
             const std::string& timescale_key);
    ~VcdTrace();  // ends the file at the current simulation time
    VcdTrace(const VcdTrace&) = delete;
    VcdTrace& operator=(const VcdTrace&) = delete;

private:
    std::ofstream m_file;
    std::optional<metrics::VcdWriter> m_writer;
};

}  // namespace cnc::sim
