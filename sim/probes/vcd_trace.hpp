// The run's VCD file (for gtkwave): SystemC's writer at 1 ps resolution, so 20 ns FPGA clocks, 62.5 ns AVR
// cycles and the CP2102's 8666.67 ns bits are all exact. Pins keep their names in every architecture.
#pragma once
#include <string>

#include <systemc>

namespace cnc::sim {

class VcdTrace {
public:
    explicit VcdTrace(const std::string& path);  // SystemC appends ".vcd": a path ending in .vcd is taken as is
    ~VcdTrace();
    VcdTrace(const VcdTrace&) = delete;
    VcdTrace& operator=(const VcdTrace&) = delete;

    void trace(const sc_core::sc_signal<bool>& signal);

private:
    sc_core::sc_trace_file* m_file;
};

}  // namespace cnc::sim
