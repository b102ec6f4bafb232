// The lathe-sync run's VCD (trace.vcd, --vcd): the ATmega16's pins as the rig recorded them (lathe::traced_pins:
// OC1A's PWM to the L298's EnA, DIR1/DIR2, the encoder pulses at INT0/INT1, the index, the limit switch, the
// keypad's columns and rows, the LCD's RS, R/W, E and D4..D7), each in the scope of the part wired to it, each edge
// at its 8 MHz clock cycle, with trace.signals, trace.from_s / trace.to_s and trace.timescale as for the other
// architectures.
#pragma once
#include <optional>
#include <vector>

#include "lathe/rig/lathe_rig.hpp"
#include "metrics/vcd/vcd_writer.hpp"
#include "output/gtkw_save.hpp"
#include "output/output_file.hpp"
#include "scenario/scenario.hpp"

namespace cnc::sim {

class LatheTrace {
public:
    // Before the run: BadInput naming trace.signals or trace.timescale for a name or unit the trace cannot take,
    // the file when it cannot be written.
    // `clock_hz`: the ATmega16's clock when its edges fall on a whole-picosecond grid.
    LatheTrace(const Scenario& s, std::optional<std::int64_t> clock_hz);

    // After the run: writes the rig's edges (LatheRigConfig::trace_pins) and closes the file.
    void write(const lathe::LatheRig& rig);
    // What the file holds, for its gtkwave save file (once written).
    [[nodiscard]] const TraceLayout& layout() const { return m_layout; }

private:
    const Scenario& m_s;
    std::vector<std::size_t> m_chosen;  // indices into lathe::traced_pins()
    std::vector<metrics::VcdSignal> m_signals;
    std::optional<OutputFile> m_file;
    TraceLayout m_layout;
};

}  // namespace cnc::sim
