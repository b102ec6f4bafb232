// SystemC bench for the spi-fpga link: an SPI master driven by a scripted host thread, the FPGA top, and a
// recorder on every pin. Several benches can live in one elaboration (e.g. wires vs transactions, or the two
// rate-apply modes side by side).
#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <systemc>
#include <vector>

#include "common/edge_log.hpp"
#include "fpga/spi/spi_fpga_top.hpp"
#include "spi/spi_master.hpp"

namespace cnc::spi::test {

constexpr TimePs kUs = kPsPerUs;
constexpr TimePs kMs = kPsPerMs;
constexpr TimePs kCyclePs = 20'000;  // 50 MHz

class PinRecorder : public sc_core::sc_module {
public:
    sc_core::sc_in<bool> pin;
    explicit PinRecorder(const sc_core::sc_module_name& name);
    EdgeLog log;

private:
    void on_change();
    bool m_started = false;
};

struct Send {
    TimePs t_ps = 0;  // transfer() is called at this time
    std::vector<std::uint8_t> mosi;
};

class SpiBench : public sc_core::sc_module {
public:
    SpiBench(const sc_core::sc_module_name& name, const SpiConfig& link, const fpga::SpiFpgaConfig& fpga_cfg,
             std::vector<Send> script);

    [[nodiscard]] const EdgeLog& log(const std::string& pin) const { return m_recorders.at(pin)->log; }
    [[nodiscard]] const std::vector<std::vector<std::uint8_t>>& replies() const { return m_replies; }

    sc_core::sc_signal<bool> sclk{"sclk", false};
    sc_core::sc_signal<bool> mosi{"mosi", false};
    sc_core::sc_signal<bool> ss{"ss", true};
    sc_core::sc_signal<bool> miso{"miso", false};
    sc_core::sc_signal<bool> step_x{"step_x", false};
    sc_core::sc_signal<bool> dir_x{"dir_x", false};
    sc_core::sc_signal<bool> step_y{"step_y", false};
    sc_core::sc_signal<bool> dir_y{"dir_y", false};
    sc_core::sc_signal<bool> laser{"laser", false};
    SpiMaster master;
    fpga::SpiFpgaTop fpga;

private:
    void host_thread();
    std::vector<Send> m_script;
    std::vector<std::vector<std::uint8_t>> m_replies;
    std::map<std::string, PinRecorder*> m_recorders;
    std::vector<std::unique_ptr<PinRecorder>> m_owned;
};

// Command frame bytes for two axes (min period 1 so that tests can also build short words).
std::vector<std::uint8_t> rates(AxisRate x, AxisRate y, bool laser_on = false);
// STEP rise edges (clock indices) of a log.
std::vector<std::int64_t> rise_edges(const EdgeLog& log);
std::vector<std::int64_t> fall_edges(const EdgeLog& log);
std::vector<std::int64_t> change_edges(const EdgeLog& log);
// first, first + period, ... (count values)
std::vector<std::int64_t> train(std::int64_t first, std::int64_t period, std::int64_t count);
// Rises (as edges) in [from, to).
std::vector<std::int64_t> between(const std::vector<std::int64_t>& edges, std::int64_t from, std::int64_t to);
// The edge at which the FPGA first samples a change at t, and the frame-end push edge for an SS rise at t.
inline std::int64_t sample_edge(TimePs t) {
    return first_edge_after(t, kCyclePs);
}
inline std::int64_t push_edge(TimePs t_ss_rise) {
    return sample_edge(t_ss_rise) + 2;
}

}  // namespace cnc::spi::test
