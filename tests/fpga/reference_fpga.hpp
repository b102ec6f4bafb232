// Cycle-ticked REFERENCE of the seed 000 FPGA for the tests: one tick() per clock edge, each always block of
// top.v, uart_rx.v, packet_decoder.v, step_gen.v, laser_ctrl.v and uart_tx.v translated into a next-state
// function on plain registers (non-blocking semantics: every block reads the registers as they were before the
// edge). Deliberately shares no code with the event-driven models it checks.
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "common/edge_log.hpp"
#include "fpga/core/fpga_config.hpp"

namespace cnc::fpga::ref {

struct UartRxRegs {
    std::uint8_t state = 0;
    std::uint32_t count = 0;  // [9:0]
    std::uint8_t bit_idx = 0;
    std::uint8_t rx_shift = 0;
    std::uint8_t rx_data = 0;
    bool rx_valid = false;
    bool rx_s1 = true;
    bool rx_s2 = true;
};

struct DecoderRegs {
    std::uint32_t byte_count = 0;   // [3:0]
    std::uint32_t timeout_cnt = 0;  // [22:0]
    bool timeout_active = false;
    bool is_cfg_pkt = false;
    std::uint8_t b[10] = {};
    std::uint8_t motion = 0;
    std::uint32_t steps_x = 0;
    std::uint32_t steps_y = 0;
    std::uint16_t feed_rate = 0;
    bool pkt_valid = false;
    std::uint32_t numerator_x = 0;
    std::uint32_t numerator_y = 0;
    bool cfg_valid = false;
};

struct StepGenRegs {
    std::uint8_t state = 0;
    bool dir_x = false, step_x = false, dir_y = false, step_y = false, busy = false;
    std::uint32_t num_x = 0, num_y = 0;
    std::uint32_t abs_x = 0, abs_y = 0, rem_x = 0, rem_y = 0;
    std::uint32_t period_x = 0, period_y = 0, cnt_x = 0, cnt_y = 0;
    std::uint32_t dir_cnt = 0;  // [8:0]
};

struct LaserRegs {
    bool laser = false;
    bool engrave = false;
};

struct UartTxRegs {
    std::uint8_t state = 0;
    std::uint32_t clk_count = 0;  // [8:0]
    std::uint8_t bit_index = 0;
    std::uint8_t tx_shift = 0;
    bool tx_busy = false;
    bool tx = true;
};

struct TopRegs {
    bool busy_prev = false;
    bool tx_start = false;
    std::uint8_t pkt_count = 0;
};

class RefFpga {
public:
    explicit RefFpga(const FpgaConfig& cfg);

    // One rising clock edge; rx is the line level this edge samples into rx_s1.
    void tick(bool rx);
    [[nodiscard]] std::int64_t edge() const { return m_edge; }
    [[nodiscard]] const std::map<std::string, EdgeLog>& logs() const { return m_logs; }

private:
    UartRxRegs uart_rx_next(bool rx) const;
    DecoderRegs decoder_next() const;
    StepGenRegs step_gen_next() const;
    LaserRegs laser_next() const;
    UartTxRegs uart_tx_next() const;
    TopRegs top_next() const;
    void log_outputs();

    FpgaConfig m_cfg;
    std::int64_t m_edge = 0;
    UartRxRegs m_rx;
    DecoderRegs m_dec;
    StepGenRegs m_sg;
    LaserRegs m_laser;
    UartTxRegs m_tx;
    TopRegs m_top;
    std::map<std::string, EdgeLog> m_logs;
};

// Runs the reference from reset over edges 1..last_edge with the rx line given by its changes (idle high
// before the first one); returns the output pin logs.
std::map<std::string, EdgeLog> run_reference(const FpgaConfig& cfg, const std::vector<Edge>& rx_changes,
                                             std::int64_t last_edge);

}  // namespace cnc::fpga::ref
