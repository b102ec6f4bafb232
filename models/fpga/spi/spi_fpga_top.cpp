#include "fpga/spi/spi_fpga_top.hpp"

namespace cnc::fpga {

namespace {
const SpiFpgaConfig& validated(const SpiFpgaConfig& cfg) {
    validate(cfg);
    return cfg;
}
}  // namespace

SpiFpgaTop::SpiFpgaTop(const sc_core::sc_module_name& name, const SpiFpgaConfig& cfg)
    : SpiBoard(name),
      spi_target("spi_target"),
      m_cfg(validated(cfg)),
      slave("spi_slave", m_cfg, kAxes),
      fifo("cmd_fifo", m_cfg, kAxes),
      pulse_gen_x("pulse_gen_x", m_cfg, 0),
      pulse_gen_y("pulse_gen_y", m_cfg, 1),
      step_counter_x("step_counter_x", m_cfg),
      step_counter_y("step_counter_y", m_cfg),
      laser_latch("laser_latch") {
    slave.sclk(sclk);
    slave.mosi(mosi);
    slave.ss(ss);
    slave.miso(miso);
    slave.fifo(fifo);
    slave.counters(step_counter_x);
    slave.counters(step_counter_y);
    spi_target(slave);
    pulse_gen_x.fifo(fifo);
    pulse_gen_x.step(step_x);
    pulse_gen_x.dir(dir_x);
    pulse_gen_y.fifo(fifo);
    pulse_gen_y.step(step_y);
    pulse_gen_y.dir(dir_y);
    // The counters read the generators' output pins back, as the RTL reads its own STEP/DIR registers.
    step_counter_x.step(step_x);
    step_counter_x.dir(dir_x);
    step_counter_y.step(step_y);
    step_counter_y.dir(dir_y);
    laser_latch.fifo(fifo);
    laser_latch.laser(laser);
}

void SpiFpgaTop::keep_frame_logs(bool on) {
    slave.keep_frame_log(on);
    fifo.keep_logs(on);
}

const std::vector<AppliedRate>& SpiFpgaTop::applied(std::size_t axis) const {
    return (axis == 0 ? pulse_gen_x : pulse_gen_y).applied();
}

std::vector<AppliedRate> SpiFpgaTop::take_applied(std::size_t axis) {
    return (axis == 0 ? pulse_gen_x : pulse_gen_y).take_applied();
}

std::uint64_t SpiFpgaTop::applied_count(std::size_t axis) const {
    return (axis == 0 ? pulse_gen_x : pulse_gen_y).applied_count();
}

std::int32_t SpiFpgaTop::count(std::size_t axis) const {
    return (axis == 0 ? step_counter_x : step_counter_y).count();
}

SpiFpgaStats SpiFpgaTop::stats() const {
    SpiFpgaStats st;
    st.frames = slave.frame_count();
    st.frames_accepted = slave.accepted_count();
    st.fifo_drops = fifo.core().dropped();
    st.fifo_max_level = fifo.core().max_level();
    st.stretched_words = pulse_gen_x.stretched() + pulse_gen_y.stretched();
    for (std::size_t a = 0; a < kAxes; ++a) {
        st.words_applied[a] = applied_count(a);
        st.counts[a] = count(a);
    }
    return st;
}

std::uint64_t SpiFpgaTop::activations() const {
    return slave.activations() + pulse_gen_x.activations() + pulse_gen_y.activations() + step_counter_x.activations() +
           step_counter_y.activations() + laser_latch.activations();
}

void SpiFpgaTop::add_traces(sc_core::sc_trace_file* tf) const {
    for (const auto* pin : {&sclk, &mosi, &ss}) sc_core::sc_trace(tf, *pin, pin->name());
    for (const auto* pin : {&miso, &step_x, &dir_x, &step_y, &dir_y, &laser}) sc_core::sc_trace(tf, *pin, pin->name());
}

}  // namespace cnc::fpga
