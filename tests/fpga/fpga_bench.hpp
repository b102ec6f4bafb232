// SystemC test bench for the FPGA top: drives rx from a list of level changes and logs every output pin.
#pragma once
#include <map>
#include <memory>
#include <string>
#include <systemc>
#include <vector>

#include "common/edge_log.hpp"
#include "fpga/top.hpp"

namespace cnc::fpga::test {

class PinMonitor : public sc_core::sc_module {
public:
    sc_core::sc_in<bool> pin;
    PinMonitor(const sc_core::sc_module_name& name, bool initial);
    EdgeLog log;

private:
    void record();
};

class FpgaBench : public sc_core::sc_module {
public:
    // `estop_changes`, `lid_changes`: the safety inputs' levels (with cfg's estop_input, interlock_input).
    FpgaBench(const sc_core::sc_module_name& name, const FpgaConfig& cfg, std::vector<Edge> rx_changes,
              std::vector<Edge> estop_changes = {}, std::vector<Edge> lid_changes = {});

    [[nodiscard]] std::map<std::string, EdgeLog> logs() const;
    // Runs the simulation up to (not including) edge `edge` + half a period.
    void run_to_edge(std::int64_t edge);

    Top top;

private:
    void drive_rx();
    void drive_estop();
    void drive_lid();

    std::vector<Edge> m_rx_changes;
    std::vector<Edge> m_estop_changes;
    std::vector<Edge> m_lid_changes;
    sc_core::sc_signal<bool> m_estop{"estop", false};
    sc_core::sc_signal<bool> m_lid_open{"lid_open", false};
    ClockGrid m_clock;
    sc_core::sc_signal<bool> m_rx{"rx", true};
    std::vector<std::unique_ptr<sc_core::sc_signal<bool>>> m_pins;
    std::vector<std::unique_ptr<PinMonitor>> m_monitors;
};

// The pins compared between the reference and the model.
const std::vector<std::string>& fpga_pins();

}  // namespace cnc::fpga::test
