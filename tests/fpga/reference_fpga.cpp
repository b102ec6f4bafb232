#include "reference_fpga.hpp"

#include <algorithm>
#include <limits>

namespace cnc::fpga::ref {

namespace {
// uart_rx states
constexpr std::uint8_t S_IDLE = 0, S_START = 1, S_RECEIVE = 2, S_STOP = 3;
// step_gen states
constexpr std::uint8_t IDLE = 0, SETUP = 1, DIR_WAIT = 2, RUN = 3, DONE = 4;
// uart_tx states
constexpr std::uint8_t TX_IDLE = 0, TX_START = 1, TX_DATA = 2, TX_STOP = 3;

std::uint32_t cat32(std::uint8_t a, std::uint8_t b, std::uint8_t c, std::uint8_t d) {
    return (std::uint32_t{a} << 24) | (std::uint32_t{b} << 16) | (std::uint32_t{c} << 8) | d;
}
}  // namespace

RefFpga::RefFpga(const FpgaConfig& cfg) : m_cfg(cfg) {
    m_dec.numerator_x = m_dec.numerator_y = cfg.numerator_default;
    m_sg.num_x = m_sg.num_y = cfg.numerator_default;
    for (const char* pin : {"tx", "dir_x", "step_x", "dir_y", "step_y", "laser", "busy", "pkt_valid", "cfg_valid",
                            "rx_valid", "tx_start"}) {
        m_logs[pin] = EdgeLog{pin, std::string(pin) == "tx", {}};
    }
}

UartRxRegs RefFpga::uart_rx_next(bool rx) const {
    const UartRxRegs& r = m_rx;
    UartRxRegs n = r;
    const std::uint32_t full = m_cfg.uart_full_bit_cycles;
    const std::uint32_t half = m_cfg.uart_half_bit_cycles;
    n.rx_s1 = rx;
    n.rx_s2 = r.rx_s1;
    n.rx_valid = false;
    switch (r.state) {
        case S_IDLE:
            n.count = 0;
            n.bit_idx = 0;
            if (!r.rx_s2) {
                n.state = S_START;
                n.count = 1;
            }
            break;
        case S_START:
            if (r.count == half) {
                if (!r.rx_s2) {
                    n.count = 1;
                    n.state = S_RECEIVE;
                } else {
                    n.state = S_IDLE;
                    n.count = 0;
                }
            } else {
                n.count = (r.count + 1) & 0x3FF;
            }
            break;
        case S_RECEIVE:
            if (r.count == full) {
                n.count = 1;
                n.rx_shift = static_cast<std::uint8_t>((r.rx_shift & ~(1U << r.bit_idx)) |
                                                       (static_cast<unsigned>(r.rx_s2) << r.bit_idx));
                if (r.bit_idx == 7) {
                    n.bit_idx = 0;
                    n.state = S_STOP;
                } else {
                    n.bit_idx = static_cast<std::uint8_t>(r.bit_idx + 1);
                }
            } else {
                n.count = (r.count + 1) & 0x3FF;
            }
            break;
        default:  // S_STOP
            if (r.count == full) {
                n.count = 0;
                n.state = S_IDLE;
                if (r.rx_s2) {
                    n.rx_data = r.rx_shift;
                    n.rx_valid = true;
                }
            } else {
                n.count = (r.count + 1) & 0x3FF;
            }
            break;
    }
    return n;
}

DecoderRegs RefFpga::decoder_next() const {
    const DecoderRegs& r = m_dec;
    DecoderRegs n = r;
    const bool rx_valid = m_rx.rx_valid;
    const std::uint8_t rx_data = m_rx.rx_data;
    n.pkt_valid = false;
    n.cfg_valid = false;
    if (r.timeout_active) {
        if (rx_valid) {
            n.timeout_cnt = 0;
        } else {
            n.timeout_cnt = (r.timeout_cnt + 1) & 0x7FFFFF;
            if (r.timeout_cnt >= m_cfg.watchdog_cycles - 1) {
                n.byte_count = 0;
                n.timeout_cnt = 0;
                n.timeout_active = false;
                n.is_cfg_pkt = false;
            }
        }
    }
    if (rx_valid) {
        n.timeout_cnt = 0;
        if (r.byte_count <= 9) n.b[r.byte_count] = rx_data;
        if (r.byte_count == 0) {
            n.timeout_active = true;
            n.is_cfg_pkt = rx_data == 0xFF;
        }
        if (r.is_cfg_pkt && r.byte_count == 8) {
            n.numerator_x = cat32(r.b[1], r.b[2], r.b[3], r.b[4]);
            n.numerator_y = cat32(r.b[5], r.b[6], r.b[7], rx_data);
            n.cfg_valid = true;
            n.byte_count = 0;
            n.timeout_active = false;
            n.timeout_cnt = 0;
            n.is_cfg_pkt = false;
        } else if (!r.is_cfg_pkt && r.byte_count == 10) {
            n.motion = r.b[0] & 0x3;
            n.steps_x = cat32(r.b[1], r.b[2], r.b[3], r.b[4]);
            n.steps_y = cat32(r.b[5], r.b[6], r.b[7], r.b[8]);
            n.feed_rate = static_cast<std::uint16_t>((r.b[9] << 8) | rx_data);
            n.pkt_valid = true;
            n.byte_count = 0;
            n.timeout_active = false;
            n.timeout_cnt = 0;
        } else {
            n.byte_count = (r.byte_count + 1) & 0xF;
        }
    }
    return n;
}

StepGenRegs RefFpga::step_gen_next() const {
    const StepGenRegs& r = m_sg;
    StepGenRegs n = r;
    const DecoderRegs& d = m_dec;
    const bool wired = m_cfg.init_packet_wired;
    const bool cfg_valid = wired && d.cfg_valid;  // unconnected input tied low
    const std::uint32_t numerator_x = wired ? d.numerator_x : 0;
    const std::uint32_t numerator_y = wired ? d.numerator_y : 0;
    const std::uint32_t feed = d.feed_rate;
    const std::uint32_t pulse_high = m_cfg.pulse_high_cycles;

    // period_sub = (num / feed) * abs_dom / abs_sub at 32 bits (appendix) or with a 64-bit product (text).
    auto subordinate = [&](std::uint32_t per_step, std::uint32_t abs_dom, std::uint32_t abs_sub) -> std::uint32_t {
        if (m_cfg.period_arithmetic == PeriodArithmetic::Wrap32) return per_step * abs_dom / abs_sub;
        const std::uint64_t q = std::uint64_t{per_step} * abs_dom / abs_sub;
        return static_cast<std::uint32_t>(std::min<std::uint64_t>(q, std::numeric_limits<std::uint32_t>::max()));
    };

    if (cfg_valid && r.state == IDLE) {
        n.num_x = numerator_x;
        n.num_y = numerator_y;
    }
    switch (r.state) {
        case IDLE:
            n.step_x = false;
            n.step_y = false;
            n.busy = false;
            if (d.pkt_valid) {
                n.busy = true;
                n.state = SETUP;
            }
            break;
        case SETUP:
            n.dir_x = (d.steps_x >> 31) == 0;
            n.dir_y = (d.steps_y >> 31) == 0;
            n.abs_x = (d.steps_x >> 31) ? ~d.steps_x + 1 : d.steps_x;
            n.abs_y = (d.steps_y >> 31) ? ~d.steps_y + 1 : d.steps_y;
            n.dir_cnt = 0;
            n.state = DIR_WAIT;
            break;
        case DIR_WAIT:
            if (r.dir_cnt == 0) {
                n.rem_x = r.abs_x;
                n.rem_y = r.abs_y;
                n.cnt_x = 0;
                n.cnt_y = 0;
                if (feed == 0) {
                    n.period_x = m_cfg.feed_zero_period_cycles;
                    n.period_y = m_cfg.feed_zero_period_cycles;
                } else if (r.abs_x == 0 && r.abs_y == 0) {
                    n.period_x = 0;
                    n.period_y = 0;
                } else if (r.abs_x >= r.abs_y) {
                    n.period_x = r.num_x / feed;
                    n.period_y = r.abs_y == 0 ? 0 : subordinate(r.num_x / feed, r.abs_x, r.abs_y);
                } else {
                    n.period_y = r.num_y / feed;
                    n.period_x = r.abs_x == 0 ? 0 : subordinate(r.num_y / feed, r.abs_y, r.abs_x);
                }
            }
            if (r.dir_cnt >= m_cfg.dir_settle_cycles - 1) {
                n.dir_cnt = 0;
                n.state = (r.abs_x == 0 && r.abs_y == 0) ? DONE : RUN;
            } else {
                n.dir_cnt = (r.dir_cnt + 1) & 0x1FF;
            }
            break;
        case RUN:
            if (r.rem_x > 0 && r.period_x > 0) {
                if (r.cnt_x == 0) {
                    n.step_x = true;
                } else if (r.cnt_x == pulse_high) {
                    n.step_x = false;
                }
                if (r.cnt_x >= r.period_x - 1) {
                    n.cnt_x = 0;
                    n.rem_x = r.rem_x - 1;
                } else {
                    n.cnt_x = r.cnt_x + 1;
                }
            } else {
                n.step_x = false;
            }
            if (r.rem_y > 0 && r.period_y > 0) {
                if (r.cnt_y == 0) {
                    n.step_y = true;
                } else if (r.cnt_y == pulse_high) {
                    n.step_y = false;
                }
                if (r.cnt_y >= r.period_y - 1) {
                    n.cnt_y = 0;
                    n.rem_y = r.rem_y - 1;
                } else {
                    n.cnt_y = r.cnt_y + 1;
                }
            } else {
                n.step_y = false;
            }
            if ((((r.rem_x == 1) && (r.cnt_x == r.period_x - 1)) || r.rem_x == 0 || r.period_x == 0) &&
                (((r.rem_y == 1) && (r.cnt_y == r.period_y - 1)) || r.rem_y == 0 || r.period_y == 0)) {
                n.step_x = false;
                n.step_y = false;
                n.state = DONE;
            }
            break;
        case DONE:
            n.busy = false;
            n.step_x = false;
            n.step_y = false;
            n.state = IDLE;
            break;
        default:
            n.state = IDLE;
            break;
    }
    return n;
}

LaserRegs RefFpga::laser_next() const {
    LaserRegs n = m_laser;
    if (m_dec.pkt_valid) n.engrave = m_dec.motion == 1 || m_dec.motion == 2 || m_dec.motion == 3;
    n.laser = m_laser.engrave && m_sg.busy;
    return n;
}

UartTxRegs RefFpga::uart_tx_next() const {
    const UartTxRegs& r = m_tx;
    UartTxRegs n = r;
    const std::uint32_t last = m_cfg.uart_full_bit_cycles - 1;
    switch (r.state) {
        case TX_IDLE:
            n.tx = true;
            n.tx_busy = false;
            if (m_top.tx_start) {
                n.tx_shift = 0xAA;  // top.v: .tx_data(8'hAA)
                n.tx_busy = true;
                n.clk_count = 0;
                n.state = TX_START;
            }
            break;
        case TX_START:
            n.tx = false;
            if (r.clk_count == last) {
                n.clk_count = 0;
                n.bit_index = 0;
                n.state = TX_DATA;
            } else {
                n.clk_count = (r.clk_count + 1) & 0x1FF;
            }
            break;
        case TX_DATA:
            n.tx = ((r.tx_shift >> r.bit_index) & 1U) != 0;
            if (r.clk_count == last) {
                n.clk_count = 0;
                if (r.bit_index == 7) {
                    n.bit_index = 0;
                    n.state = TX_STOP;
                } else {
                    n.bit_index = static_cast<std::uint8_t>(r.bit_index + 1);
                }
            } else {
                n.clk_count = (r.clk_count + 1) & 0x1FF;
            }
            break;
        default:  // TX_STOP
            n.tx = true;
            if (r.clk_count == last) {
                n.clk_count = 0;
                n.tx_busy = false;
                n.state = TX_IDLE;
            } else {
                n.clk_count = (r.clk_count + 1) & 0x1FF;
            }
            break;
    }
    return n;
}

TopRegs RefFpga::top_next() const {
    TopRegs n = m_top;
    n.tx_start = false;
    n.busy_prev = m_sg.busy;
    if (m_top.busy_prev && !m_sg.busy) {
        if (!m_tx.tx_busy) n.tx_start = true;
        n.pkt_count = static_cast<std::uint8_t>(m_top.pkt_count + 1);
    }
    return n;
}

void RefFpga::tick(bool rx) {
    ++m_edge;
    const UartRxRegs rx_n = uart_rx_next(rx);
    const DecoderRegs dec_n = decoder_next();
    const StepGenRegs sg_n = step_gen_next();
    const LaserRegs laser_n = laser_next();
    const UartTxRegs tx_n = uart_tx_next();
    const TopRegs top_n = top_next();
    m_rx = rx_n;
    m_dec = dec_n;
    m_sg = sg_n;
    m_laser = laser_n;
    m_tx = tx_n;
    m_top = top_n;
    log_outputs();
}

void RefFpga::log_outputs() {
    const TimePs t = clock_grid(m_cfg).at(m_edge);
    auto log = [&](const char* pin, bool level) {
        EdgeLog& l = m_logs[pin];
        const bool prev = l.edges.empty() ? l.initial : l.edges.back().level;
        if (prev != level) l.add(t, level);
    };
    log("tx", m_tx.tx);
    log("dir_x", m_sg.dir_x);
    log("step_x", m_sg.step_x);
    log("dir_y", m_sg.dir_y);
    log("step_y", m_sg.step_y);
    log("laser", m_laser.laser);
    log("busy", m_sg.busy);
    log("pkt_valid", m_dec.pkt_valid);
    log("cfg_valid", m_dec.cfg_valid);
    log("rx_valid", m_rx.rx_valid);
    log("tx_start", m_top.tx_start);
}

std::map<std::string, EdgeLog> run_reference(const FpgaConfig& cfg, const std::vector<Edge>& rx_changes,
                                             std::int64_t last_edge) {
    RefFpga fpga(cfg);
    const ClockGrid clock = clock_grid(cfg);
    std::size_t next = 0;
    bool level = true;
    for (std::int64_t n = 1; n <= last_edge; ++n) {
        while (next < rx_changes.size() && rx_changes[next].t_ps < clock.at(n)) level = rx_changes[next++].level;
        fpga.tick(level);
    }
    return fpga.logs();
}

}  // namespace cnc::fpga::ref
