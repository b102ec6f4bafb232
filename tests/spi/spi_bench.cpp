#include "spi_bench.hpp"

#include <memory>

namespace cnc::spi::test {

PinRecorder::PinRecorder(const sc_core::sc_module_name& name) : sc_module(name), pin("pin") {
    SC_HAS_PROCESS(PinRecorder);
    SC_METHOD(on_change);
    sensitive << pin;
}

void PinRecorder::on_change() {
    const bool level = pin.read();
    if (!m_started) {  // initialisation run: the level at time 0
        m_started = true;
        log.initial = level;
        return;
    }
    log.add(static_cast<TimePs>(sc_core::sc_time_stamp().value()), level);
}

SpiBench::SpiBench(const sc_core::sc_module_name& name, const SpiConfig& link, const fpga::SpiFpgaConfig& fpga_cfg,
                   std::vector<Send> script)
    : sc_module(name), master("master", link), fpga("fpga", fpga_cfg), m_script(std::move(script)) {
    SC_HAS_PROCESS(SpiBench);
    master.sclk(sclk);
    master.mosi(mosi);
    master.ss(ss);
    master.miso(miso);
    master.target(fpga.spi_target);
    fpga.sclk(sclk);
    fpga.mosi(mosi);
    fpga.ss(ss);
    fpga.miso(miso);
    fpga.step_x(step_x);
    fpga.dir_x(dir_x);
    fpga.step_y(step_y);
    fpga.dir_y(dir_y);
    fpga.laser(laser);
    for (auto* sig : {&sclk, &mosi, &ss, &miso, &step_x, &dir_x, &step_y, &dir_y, &laser}) {
        const std::string pin = sig->basename();
        m_owned.push_back(std::make_unique<PinRecorder>(("rec_" + pin).c_str()));
        m_owned.back()->pin(*sig);
        m_recorders[pin] = m_owned.back().get();
    }
    SC_THREAD(host_thread);
}

void SpiBench::host_thread() {
    for (const Send& s : m_script) {
        const TimePs now = static_cast<TimePs>(sc_core::sc_time_stamp().value());
        if (s.t_ps > now) sc_core::wait(sc_core::sc_time::from_value(static_cast<sc_dt::uint64>(s.t_ps - now)));
        std::vector<std::uint8_t> in;
        master.transfer(s.mosi, in);
        m_replies.push_back(in);
    }
}

std::vector<std::uint8_t> rates(AxisRate x, AxisRate y, bool laser_on) {
    return encode_command({{x, y}, laser_on}, 1);
}

namespace {
std::vector<std::int64_t> to_edges(const std::vector<TimePs>& times) {
    std::vector<std::int64_t> out;
    for (const TimePs t : times) out.push_back(t / kCyclePs);
    return out;
}
}  // namespace

std::vector<std::int64_t> rise_edges(const EdgeLog& log) {
    return to_edges(log.rising());
}
std::vector<std::int64_t> fall_edges(const EdgeLog& log) {
    return to_edges(log.falling());
}
std::vector<std::int64_t> change_edges(const EdgeLog& log) {
    std::vector<std::int64_t> out;
    for (const Edge& e : log.edges) out.push_back(e.t_ps / kCyclePs);
    return out;
}

std::vector<std::int64_t> train(std::int64_t first, std::int64_t period, std::int64_t count) {
    std::vector<std::int64_t> out;
    for (std::int64_t k = 0; k < count; ++k) out.push_back(first + k * period);
    return out;
}

std::vector<std::int64_t> between(const std::vector<std::int64_t>& edges, std::int64_t from, std::int64_t to) {
    std::vector<std::int64_t> out;
    for (const std::int64_t e : edges) {
        if (e >= from && e < to) out.push_back(e);
    }
    return out;
}

}  // namespace cnc::spi::test
