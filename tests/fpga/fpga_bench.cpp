#include "fpga_bench.hpp"

namespace cnc::fpga::test {

const std::vector<std::string>& fpga_pins() {
    static const std::vector<std::string> pins{"tx",   "dir_x",     "step_x",    "dir_y",    "step_y",  "laser",
                                               "busy", "pkt_valid", "cfg_valid", "rx_valid", "tx_start"};
    return pins;
}

PinMonitor::PinMonitor(const sc_core::sc_module_name& name, bool initial)
    : sc_module(name), pin("pin"), log{std::string(basename()), initial, {}} {
    SC_HAS_PROCESS(PinMonitor);
    SC_METHOD(record);
    sensitive << pin;
    dont_initialize();
}

void PinMonitor::record() {
    log.add(static_cast<TimePs>(sc_core::sc_time_stamp().value()), pin.read());
}

FpgaBench::FpgaBench(const sc_core::sc_module_name& name, const FpgaConfig& cfg, std::vector<Edge> rx_changes,
                     std::vector<Edge> estop_changes, std::vector<Edge> lid_changes)
    : sc_module(name),
      top("top", cfg),
      m_rx_changes(std::move(rx_changes)),
      m_estop_changes(std::move(estop_changes)),
      m_lid_changes(std::move(lid_changes)),
      m_clock(clock_grid(cfg)) {
    SC_HAS_PROCESS(FpgaBench);
    top.rx(m_rx);
    for (const std::string& pin : fpga_pins()) {
        const bool initial = pin == "tx";  // the ACK line idles high
        m_pins.push_back(std::make_unique<sc_core::sc_signal<bool>>((pin + "_sig").c_str(), initial));
        m_monitors.push_back(std::make_unique<PinMonitor>(pin.c_str(), initial));
        m_monitors.back()->pin(*m_pins.back());
    }
    sc_core::sc_out<bool>* ports[] = {&top.tx,        &top.dir_x,    &top.step_x,  &top.dir_y,
                                      &top.step_y,    &top.laser,    &top.busy,    &top.pkt_valid,
                                      &top.cfg_valid, &top.rx_valid, &top.tx_start};
    for (std::size_t i = 0; i < m_pins.size(); ++i) (*ports[i])(*m_pins[i]);
    if (cfg.estop_input) top.estop(m_estop);
    if (cfg.interlock_input) top.lid_open(m_lid_open);
    SC_THREAD(drive_rx);
    SC_THREAD(drive_estop);
    SC_THREAD(drive_lid);
}

namespace {
void drive(sc_core::sc_signal<bool>& line, const std::vector<Edge>& changes) {
    for (const Edge& e : changes) {
        const auto now = static_cast<TimePs>(sc_core::sc_time_stamp().value());
        if (e.t_ps > now) sc_core::wait(sc_core::sc_time::from_value(static_cast<sc_dt::uint64>(e.t_ps - now)));
        line.write(e.level);
    }
}
}  // namespace

void FpgaBench::drive_rx() {
    drive(m_rx, m_rx_changes);
}

void FpgaBench::drive_estop() {
    drive(m_estop, m_estop_changes);
}

void FpgaBench::drive_lid() {
    drive(m_lid_open, m_lid_changes);
}

std::map<std::string, EdgeLog> FpgaBench::logs() const {
    std::map<std::string, EdgeLog> out;
    for (const auto& m : m_monitors) out[m->log.name] = m->log;
    return out;
}

void FpgaBench::run_to_edge(std::int64_t edge) {
    const TimePs target = (m_clock.at(edge) + m_clock.at(edge + 1)) / 2;
    const auto now = static_cast<TimePs>(sc_core::sc_time_stamp().value());
    sc_core::sc_start(sc_core::sc_time::from_value(static_cast<sc_dt::uint64>(target - now)));
}

}  // namespace cnc::fpga::test
