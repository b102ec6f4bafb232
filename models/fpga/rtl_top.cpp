#include "fpga/rtl_top.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "rtl/plugin_load.hpp"

namespace cnc::fpga {

namespace {

// Indices into rtl_plugin_spec's observed list.
enum Net : std::size_t {
    kRxValid,
    kPktValid,
    kCfgValid,
    kTxStart,
    kMotion,
    kStepsX,
    kStepsY,
    kFeedRate,
    kNumeratorX,
    kNumeratorY,
    kUartRxState,
    kTimeoutActive,
    kStepGenState,
    kNumX,
    kNumY,
    kPeriodX,
    kPeriodY
};

}  // namespace

RtlTop::RtlTop(const sc_core::sc_module_name& name, const FpgaConfig& cfg, const rtl::Design& design)
    : Board(name),
      m_cfg((validate(cfg), cfg)),
      m_clock(clock_grid(cfg)),
      m_spec(rtl_plugin_spec(cfg, design)),
      m_plugin(rtl::build_plugin(m_spec)),
      m_model(rtl::load_model(m_plugin)),
      m_records(cfg, m_clock, std::all_of(m_plugin.observed_present.begin(), m_plugin.observed_present.end(),
                                          [](bool present) { return present; })),
      m_writer("writer") {
    int next = static_cast<int>(m_spec.outputs.size());
    for (const bool present : m_plugin.observed_present) m_observed_index.push_back(present ? next++ : -1);
    m_values.assign(static_cast<std::size_t>(next), 0);
    m_quiet_until = [] { return now_ps(); };
    SC_HAS_PROCESS(RtlTop);
    SC_THREAD(run_thread);
}

std::uint64_t RtlTop::observed(std::size_t net) const {
    const int i = m_observed_index[net];
    return i < 0 ? 0 : m_values[static_cast<std::size_t>(i)];
}

void RtlTop::drive(sc_core::sc_out<bool>& pin, bool level, TimePs t_ps) {
    m_writer.at(t_ps, [&pin, level] { pin.write(level); });
}

void RtlTop::on_edge(std::int64_t n) {
    std::vector<std::uint64_t> before = m_values;
    for (std::size_t i = 0; i < m_values.size(); ++i) m_values[i] = m_model->value(static_cast<int>(i));
    if (n > 0 && before == m_values) return;
    const TimePs t = m_clock.at(n);
    const std::pair<sc_core::sc_out<bool>*, std::size_t> pins[] = {
        {&tx, kRtlOutTx},          {&dir_x, kRtlOutDirX}, {&step_x, kRtlOutStepX}, {&dir_y, kRtlOutDirY},
        {&step_y, kRtlOutStepY},   {&laser, kRtlOutLaser}, {&busy, kRtlOutBusy}};
    for (const auto& [pin, i] : pins) {
        if (m_values[i] != before[i] || n == 0) drive(*pin, m_values[i] != 0, t);
    }
    const std::pair<sc_core::sc_out<bool>*, Net> strobes[] = {
        {&pkt_valid, kPktValid}, {&cfg_valid, kCfgValid}, {&rx_valid, kRxValid}, {&tx_start, kTxStart}};
    for (const auto& [pin, net] : strobes) {
        const int i = m_observed_index[net];
        if (i >= 0 && m_values[static_cast<std::size_t>(i)] != before[static_cast<std::size_t>(i)]) {
            drive(*pin, m_values[static_cast<std::size_t>(i)] != 0, t);
        }
    }
    FpgaNets v;
    v.busy = m_values[kRtlOutBusy] != 0;
    v.tx = m_values[kRtlOutTx] != 0;
    v.rx_valid = observed(kRxValid) != 0;
    v.pkt_valid = observed(kPktValid) != 0;
    v.cfg_valid = observed(kCfgValid) != 0;
    v.tx_start = observed(kTxStart) != 0;
    v.timeout_active = observed(kTimeoutActive) != 0;
    v.uart_rx_state = static_cast<std::uint8_t>(observed(kUartRxState));
    v.step_gen_state = static_cast<std::uint8_t>(observed(kStepGenState));
    v.motion = static_cast<std::uint8_t>(observed(kMotion));
    v.steps_x = static_cast<std::int32_t>(static_cast<std::uint32_t>(observed(kStepsX)));
    v.steps_y = static_cast<std::int32_t>(static_cast<std::uint32_t>(observed(kStepsY)));
    v.feed_rate = static_cast<std::uint16_t>(observed(kFeedRate));
    v.numerator_x = static_cast<std::uint32_t>(observed(kNumeratorX));
    v.numerator_y = static_cast<std::uint32_t>(observed(kNumeratorY));
    v.num_x = static_cast<std::uint32_t>(observed(kNumX));
    v.num_y = static_cast<std::uint32_t>(observed(kNumY));
    v.period_x = static_cast<std::uint32_t>(observed(kPeriodX));
    v.period_y = static_cast<std::uint32_t>(observed(kPeriodY));
    m_records.edge(n, v);
}

void RtlTop::run_through(TimePs t_ps) {
    const std::int64_t last = m_clock.last_at_or_before(t_ps);
    while (m_next_edge <= last) {
        const std::uint64_t ran = m_model->run(static_cast<std::uint64_t>(last - m_next_edge + 1));
        m_next_edge += static_cast<std::int64_t>(ran);
        on_edge(m_next_edge - 1);
    }
}

void RtlTop::run_thread() {
    // Edge 0 is the reset state (top.v's rst_n is synchronous); rx idles high.
    m_rx_level = rx.read();
    m_model->set_input(kRtlInRx, m_rx_level ? 1 : 0);
    m_model->set_input(kRtlInResetN, 0);
    m_model->run(1);
    m_next_edge = 1;
    on_edge(0);
    m_model->set_input(kRtlInResetN, 1);
    for (;;) {
        const TimePs now = now_ps();
        if (rx.read() != m_rx_level) {
            if (now < m_promised_ps) {
                throw std::logic_error(std::string(name()) + ": rx changed at " + std::to_string(now) +
                                       " ps, before the " + std::to_string(m_promised_ps) + " ps promised");
            }
            run_through(now);  // an edge at the change's instant samples the level before it
            m_rx_level = rx.read();
            m_model->set_input(kRtlInRx, m_rx_level ? 1 : 0);
        }
        m_promised_ps = std::max(now, m_quiet_until());
        run_through(m_promised_ps);
        if (!m_model->settled()) {
            wait(ps(m_clock.at(m_next_edge) - now), rx.value_changed_event());
            continue;
        }
        // Nothing changes until rx does (an idle design): the edges until then are skipped, and a run whose
        // other models have finished ends here.
        wait(rx.value_changed_event());
        m_next_edge = std::max(m_next_edge, m_clock.first_after(now_ps()));
    }
}

}  // namespace cnc::fpga
