#include "fpga/core/rtl_design.hpp"

#include <algorithm>
#include <string>

#include "rtl/design_sources.hpp"

namespace cnc::fpga {

rtl::PluginSpec rtl_plugin_spec(const FpgaConfig& cfg, const rtl::Design& design) {
    rtl::PluginSpec spec;
    rtl::set_design(spec, design, "top", CNC_FPGA_RTL_DIR,
                    {"top.v", "uart_rx.v", "packet_decoder.v", "step_gen.v", "period_divider.v", "step_ramp.v",
                     "laser_ctrl.v", "uart_tx.v", "packet_queue.v"},
                    {{"CLK_HZ", std::to_string(cfg.clk_hz)},
                     {"FULL_BIT", std::to_string(cfg.uart_full_bit_cycles)},
                     {"PULSE_HIGH", std::to_string(cfg.pulse_high_cycles)},
                     {"DIR_SETTLE", std::to_string(cfg.dir_settle_cycles)},
                     {"FEED_ZERO_PERIOD", std::to_string(cfg.feed_zero_period_cycles)},
                     {"TIMEOUT_CYCLES", std::to_string(cfg.watchdog_cycles)},
                     {"NUMERATOR_DEFAULT", std::to_string(cfg.numerator_default)},
                     {"EXACT_PERIOD", cfg.period_arithmetic == PeriodArithmetic::Exact ? "1" : "0"},
                     {"INIT_WIRED", cfg.init_packet_wired ? "1" : "0"},
                     {"PACKET_CRC", cfg.packet_crc ? "1" : "0"},
                     {"LASER_PWM_PERIOD", std::to_string(cfg.laser_pwm_period_cycles)},
                     {"ESTOP", cfg.estop_input ? "1" : "0"},
                     {"INTERLOCK", cfg.interlock_input ? "1" : "0"},
                     {"RAMP", cfg.ramp == StepRamp::Trapezoidal ? "1" : "0"},
                     {"RAMP_ACCEL_DEFAULT", std::to_string(cfg.ramp_accel_default)},
                     {"RAMP_START_DEFAULT", std::to_string(cfg.ramp_start_default)},
                     {"QUEUE_DEPTH", std::to_string(cfg.queue_depth)}});
    spec.clock = "clk";
    // A top without the safety inputs runs where their options are off (they are tied low then).
    spec.inputs = {{"rst_n", 1}, {"rx", 1}, {"estop", 1, !cfg.estop_input}, {"lid_open", 1, !cfg.interlock_input}};
    spec.outputs = {{"tx", 1},     {"dir_x", 1},    {"step_x", 1}, {"n_enbl_x", 1}, {"dir_y", 1},
                    {"step_y", 1}, {"n_enbl_y", 1}, {"laser", 1},  {"busy", 1}};
    const std::string& top = spec.top_module;
    spec.observed = {{top, "rx_valid", "rx_valid"},
                     {top, "pkt_valid", "pkt_valid"},
                     {top, "cfg_valid", "cfg_valid"},
                     {top, "tx_start", "tx_start"},
                     {top, "motion", "motion"},
                     {top, "steps_x", "steps_x"},
                     {top, "steps_y", "steps_y"},
                     {top, "feed_rate", "feed_rate"},
                     {top, "numerator_x", "numerator_x"},
                     {top, "numerator_y", "numerator_y"},
                     {"uart_rx", "uart_rx_inst.state", "state"},
                     {"packet_decoder", "pkt_dec_inst.timeout_active", "timeout_active"},
                     {"step_gen", "step_gen_inst.state", "state"},
                     {"step_gen", "step_gen_inst.num_x", "num_x"},
                     {"step_gen", "step_gen_inst.num_y", "num_y"},
                     {"step_gen", "step_gen_inst.period_x", "period_x"},
                     {"step_gen", "step_gen_inst.period_y", "period_y"}};
    // Only a run with the packet check needs its nets: without it, a user's top written for the seed's packets
    // keeps its records read off its nets.
    if (cfg.packet_crc) {
        spec.observed.push_back({top, "crc_error", "crc_error"});
        spec.observed.push_back({top, "pkt_repeat", "pkt_repeat"});
        spec.observed.push_back({top, "tx_nak", "tx_nak"});
    }
    if (cfg.estop_input) {
        spec.observed.push_back({top, "halt", "halt"});
        spec.observed.push_back({top, "halted", "halted"});
    }
    if (cfg.queue_depth > 0) {
        // step_gen takes the queue's moves: they are the records (the decoder's packets are judged by the queue).
        const std::string q = "packet_queue";
        const std::string inst = "queue.packet_queue_inst.";
        for (const char* net : {"pkt_valid", "motion", "steps_x", "steps_y", "feed_rate"}) {
            auto it = std::find_if(spec.observed.begin(), spec.observed.end(),
                                   [&](const rtl::ObservedNet& n) { return n.path == net; });
            *it = {q, inst + "q_" + net, std::string("q_") + net};
        }
        spec.observed.push_back({top, "pkt_valid", "pkt_valid"});  // the decoder's: a packet ends
        spec.observed.push_back({q, inst + "queued", "queued"});
        spec.observed.push_back({q, inst + "again", "again"});
        spec.observed.push_back({q, inst + "refused", "refused"});
        spec.observed.push_back({top, "status_start", "status_start"});
    }
    return spec;
}

}  // namespace cnc::fpga
