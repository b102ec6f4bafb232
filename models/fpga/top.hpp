// top (seed 000 §5.2.6, Π.1) as event-driven blocks: uart_rx -> packet_decoder -> step_gen + laser_ctrl, uart_tx
// sending the 0xAA ACK when busy falls (only if uart_tx is idle then), wired as top.v. init_packet_wired = false
// keeps top.v's unconnected numerator path (seed 000 §5.2.6 says it must be driven). LEDR/HEX are not modelled.
// With the packet queue (fpga.queue_depth) packet_queue sits between the decoder and step_gen/laser_ctrl, and uart_tx
// sends its 2-byte statuses instead of the ACK. With the e-stop input (fpga.estop) a press, through a 2-FF
// synchroniser, halts step_gen at the edge after it is sampled (STEP and busy low, no move after: the laser follows
// busy one clock later, three clocks after the input at most) and uart_tx sends the halt byte at the edge after the
// halt, or at the first after it with uart_tx free; latched until reset.
// With the interlock (fpga.interlock) the synchronised lid input holds laser_ctrl's output off while the lid is open.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <systemc>
#include <vector>

#include "common/record_log.hpp"
#include "fpga/board.hpp"
#include "fpga/packet_queue.hpp"
#include "fpga/core/fpga_config.hpp"
#include "fpga/core/fpga_records.hpp"
#include "fpga/laser_ctrl.hpp"
#include "fpga/packet_decoder.hpp"
#include "fpga/step_gen.hpp"
#include "fpga/timed_writer.hpp"
#include "fpga/uart_rx.hpp"
#include "fpga/uart_tx.hpp"

namespace cnc::fpga {

class Top final : public Board {
public:
    Top(const sc_core::sc_module_name& name, const FpgaConfig& cfg);

    // One record per pkt_valid, in order, with the ACK outcome of accepted moves (the ones not dropped yet).
    [[nodiscard]] std::vector<PacketRecord> packets() const;
    [[nodiscard]] std::size_t packet_count() const override { return step_gen_inst.moves().size(); }
    [[nodiscard]] PacketRecord packet(std::size_t i) const override;
    // The decoder's, step_gen's and their ACKs' records go.
    void drop_packets_before(std::size_t end) override;
    [[nodiscard]] const std::vector<InitRecord>& inits() const override { return m_inits; }
    [[nodiscard]] FpgaStats stats() const override;
    [[nodiscard]] std::uint8_t pkt_count() const { return m_pkt_count; }  // top.v's 8-bit completed-move count
    [[nodiscard]] const FpgaConfig& config() const { return m_cfg; }
    [[nodiscard]] const ClockGrid& clock() const override { return m_clock; }
    // Debug: process activations of all blocks (the model must wake per edge, never per clock).
    [[nodiscard]] std::uint64_t activations() const;
    void add_traces(sc_core::sc_trace_file* tf) const;

private:
    void on_busy();
    void on_cfg_valid();
    void on_crc_error();
    void on_repeat();
    // The queue's status: its two bytes back to back, the values read when the first starts; a request while one is
    // on the wire sends a fresh one after it.
    void on_status_req();
    void on_tx_busy();
    void start_status(std::int64_t edge);
    void wire_queue(const FpgaConfig& cfg);
    void on_estop();
    void on_lid();
    // The edge at which a safety input that changes now is seen through its 2-FF synchroniser.
    [[nodiscard]] std::int64_t synchronised_edge() const;
    // The next byte for uart_tx once it is free: a status's second byte, the halt byte, a status asked for.
    void send_next_byte(std::int64_t edge);
    // The records' source: the decoder's packets, or with the queue the moves it handed step_gen.
    [[nodiscard]] const RecordLog<PacketDecoder::MotionOut>& handed_over() const;
    // tx_start for one clock at edge `edge` with tx_data = byte; an ACK wins over a NAK asked for the same edge.
    void start_tx(std::int64_t edge, std::uint8_t byte);

    const FpgaConfig m_cfg;
    const ClockGrid m_clock;
    sc_core::sc_signal<std::uint8_t> m_rx_data{"rx_data", 0};
    sc_core::sc_signal<std::uint8_t> m_motion{"motion", 0};
    sc_core::sc_signal<std::int32_t> m_steps_x{"steps_x", 0};
    sc_core::sc_signal<std::int32_t> m_steps_y{"steps_y", 0};
    sc_core::sc_signal<std::uint16_t> m_feed_rate{"feed_rate", 0};
    sc_core::sc_signal<std::uint16_t> m_laser_high{"laser_high", 0};
    sc_core::sc_signal<std::uint32_t> m_numerator_x;
    sc_core::sc_signal<std::uint32_t> m_numerator_y;
    sc_core::sc_signal<std::uint32_t> m_ramp_accel;
    sc_core::sc_signal<std::uint32_t> m_ramp_start;
    sc_core::sc_signal<std::uint32_t> m_ramp_jerk;
    sc_core::sc_signal<bool> m_tx_busy{"tx_busy", false};
    sc_core::sc_signal<std::uint8_t> m_tx_data{"tx_data", 0xAA};  // top.v: .tx_data(8'hAA), seed 000 §4.11
    sc_core::sc_signal<bool> m_crc_error{"crc_error", false};
    sc_core::sc_signal<bool> m_repeat{"repeat", false};
    sc_core::sc_signal<std::uint8_t> m_seq{"seq", 0};
    // With the queue: the decoder's strobe (the board's pkt_valid is then step_gen's) and the queue's outputs.
    sc_core::sc_signal<bool> m_decoder_pkt_valid{"decoder_pkt_valid", false};
    sc_core::sc_signal<std::uint8_t> m_q_motion{"q_motion", 0};
    sc_core::sc_signal<std::int32_t> m_q_steps_x{"q_steps_x", 0};
    sc_core::sc_signal<std::int32_t> m_q_steps_y{"q_steps_y", 0};
    sc_core::sc_signal<std::uint16_t> m_q_feed_rate{"q_feed_rate", 0};
    sc_core::sc_signal<std::uint16_t> m_q_laser_high{"q_laser_high", 0};
    sc_core::sc_signal<bool> m_status_req{"status_req", false};
    sc_core::sc_signal<bool> m_laser_inhibit{"laser_inhibit", false};
    // top.v leaves step_gen's cfg_valid/numerator inputs unconnected; synthesis ties them low.
    sc_core::sc_signal<bool> m_cfg_valid_unconnected{"cfg_valid_unconnected", false};
    sc_core::sc_signal<std::uint32_t> m_numerator_unconnected{"numerator_unconnected", 0};

public:  // instance names as in top.v
    UartRx uart_rx_inst;
    PacketDecoder pkt_dec_inst;
    StepGen step_gen_inst;
    LaserCtrl laser_ctrl_inst;
    UartTx uart_tx_inst;
    std::unique_ptr<PacketQueue> packet_queue_inst;  // with fpga.queue_depth only

private:
    TimedWriter m_writer;
    struct AckAfterBusy {
        TimePs t_busy_fall_ps;
        TimePs t_ack_start_ps;  // the tx_start edge, -1 if dropped
    };
    // One per busy fall, in time order (a sorted log: a long job's map nodes cost three times as much).
    RecordLog<AckAfterBusy> m_acks;
    std::vector<InitRecord> m_inits;
    std::uint8_t m_pkt_count = 0;
    std::uint64_t m_acks_sent = 0;
    std::uint64_t m_acks_dropped = 0;
    std::uint64_t m_naks_sent = 0;
    std::int64_t m_tx_edge = -1;  // the edge of the last tx_start asked for, and its byte
    std::uint8_t m_tx_byte = 0;
    enum class StatusTx { Idle, Byte0, Byte1 };
    StatusTx m_status_tx = StatusTx::Idle;
    bool m_status_due = false;
    std::uint8_t m_status_byte1 = 0;
    std::uint64_t m_statuses_sent = 0;
    bool m_halted = false;
    std::int64_t m_halt_edge = 0;  // the edge step_gen halts at
    bool m_halt_byte_due = false;
    TimePs m_halted_at_ps = -1;
    std::uint64_t m_activations = 0;
};

}  // namespace cnc::fpga
