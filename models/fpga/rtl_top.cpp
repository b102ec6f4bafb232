#include "fpga/rtl_top.hpp"

#include <algorithm>
#include <iterator>

namespace cnc::fpga {

namespace {

// Indices into rtl_plugin_spec's observed list.
enum Net : int {
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
    kPeriodY,
    kCrcError,  // these three with the packet check only
    kPktRepeat,
    kTxNak
};

// An observed net's index in the spec (the packet check's and the e-stop's are there with their options only).
std::size_t observed_index(const rtl::PluginSpec& spec, const char* path) {
    const auto it = std::find_if(spec.observed.begin(), spec.observed.end(),
                                 [&](const rtl::ObservedNet& net) { return net.path == path; });
    return static_cast<std::size_t>(std::distance(spec.observed.begin(), it));
}

}  // namespace

RtlTop::RtlTop(const sc_core::sc_module_name& name, const FpgaConfig& cfg, const rtl::Design& design)
    : Board(name),
      m_cfg((validate(cfg), cfg)),
      m_clock(clock_grid(cfg)),
      m_spec(rtl_plugin_spec(cfg, design)),
      m_plugin(rtl::build_plugin(m_spec)),
      m_halt_net(observed_index(m_spec, "halt")),
      m_halted_net(observed_index(m_spec, "halted")),
      m_decoder_pkt_valid_net(observed_index(m_spec, "pkt_valid")),
      m_queued_net(observed_index(m_spec, "queue.packet_queue_inst.queued")),
      m_again_net(observed_index(m_spec, "queue.packet_queue_inst.again")),
      m_refused_net(observed_index(m_spec, "queue.packet_queue_inst.refused")),
      m_status_start_net(observed_index(m_spec, "status_start")),
      m_records(cfg, m_clock,
                std::all_of(m_plugin.observed_present.begin(), m_plugin.observed_present.end(),
                            [](bool present) { return present; })),
      m_loop("rtl", m_clock, m_spec, m_plugin,
             {kRtlInResetN,
              {{&rx, kRtlInRx}, {&estop, kRtlInEstop}, {&lid_open, kRtlInLidOpen}},
              {{&tx, kRtlOutTx},
               {&dir_x, kRtlOutDirX},
               {&step_x, kRtlOutStepX},
               {&dir_y, kRtlOutDirY},
               {&step_y, kRtlOutStepY},
               {&laser, kRtlOutLaser},
               {&busy, kRtlOutBusy},
               {&pkt_valid, -1, kPktValid},
               {&cfg_valid, -1, kCfgValid},
               {&rx_valid, -1, kRxValid},
               {&tx_start, -1, kTxStart}}},
             [this](std::int64_t n) { on_edge(n); }) {
    tie_unused_inputs(cfg);
}

void RtlTop::on_edge(std::int64_t n) {
    const auto net = [this](Net i) { return m_loop.observed(static_cast<std::size_t>(i)); };
    FpgaNets v;
    v.busy = m_loop.port(kRtlOutBusy) != 0;
    v.tx = m_loop.port(kRtlOutTx) != 0;
    v.rx_valid = net(kRxValid) != 0;
    v.pkt_valid = net(kPktValid) != 0;
    v.cfg_valid = net(kCfgValid) != 0;
    v.tx_start = net(kTxStart) != 0;
    v.timeout_active = net(kTimeoutActive) != 0;
    v.uart_rx_state = static_cast<std::uint8_t>(net(kUartRxState));
    v.step_gen_state = static_cast<std::uint8_t>(net(kStepGenState));
    v.motion = static_cast<std::uint8_t>(net(kMotion));
    v.steps_x = static_cast<std::int32_t>(static_cast<std::uint32_t>(net(kStepsX)));
    v.steps_y = static_cast<std::int32_t>(static_cast<std::uint32_t>(net(kStepsY)));
    v.feed_rate = static_cast<std::uint16_t>(net(kFeedRate));
    v.numerator_x = static_cast<std::uint32_t>(net(kNumeratorX));
    v.numerator_y = static_cast<std::uint32_t>(net(kNumeratorY));
    v.num_x = static_cast<std::uint32_t>(net(kNumX));
    v.num_y = static_cast<std::uint32_t>(net(kNumY));
    v.period_x = static_cast<std::uint32_t>(net(kPeriodX));
    v.period_y = static_cast<std::uint32_t>(net(kPeriodY));
    if (m_cfg.packet_crc) {
        v.crc_error = net(kCrcError) != 0;
        v.pkt_repeat = net(kPktRepeat) != 0;
        v.tx_nak = net(kTxNak) != 0;
    }
    if (m_cfg.estop_input) {
        v.halt = m_loop.observed(m_halt_net) != 0;
        v.halted = m_loop.observed(m_halted_net) != 0;
    }
    v.decoder_pkt_valid = v.pkt_valid;
    if (m_cfg.queue_depth > 0) {
        v.decoder_pkt_valid = m_loop.observed(m_decoder_pkt_valid_net) != 0;
        v.queued = m_loop.observed(m_queued_net) != 0;
        v.again = m_loop.observed(m_again_net) != 0;
        v.refused = m_loop.observed(m_refused_net) != 0;
        v.status_start = m_loop.observed(m_status_start_net) != 0;
    }
    m_records.edge(n, v);
}

}  // namespace cnc::fpga
