// The CP2102 USB-to-UART bridge between the host program and the controller's serial pins
// (seed 000 §4.2: 115200 8N1, 3.3 V TTL, no flow control).
//
// Host side (USB): bytes written by the host reach the chip at the next USB full-speed frame start, queue in
// the 640-byte TX FIFO and are sent back to back on TXD. Bytes received on RXD enter the 576-byte RX FIFO,
// leave the chip in the next USB frame (bulk IN transfers are collected at the frame start after the byte's
// stop bit ends) and become visible to the host application after the driver latency:
//     t_host_visible = next_frame_start(t_stop_end) + usb_latency.
// The latency model is deterministic.
#pragma once
#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <systemc>
#include <vector>

#include "common/edge_log.hpp"
#include "common/record_log.hpp"
#include "common/units.hpp"
#include "uart/core/cp2102_baud.hpp"
#include "uart/core/cp2102_config.hpp"
#include "uart/core/uart_frame.hpp"
#include "uart/core/usb_timing.hpp"

namespace cnc::uart {

struct Cp2102Stats {
    std::int64_t tx_bytes = 0;           // bytes whose start bit went out on TXD
    TimePs tx_line_busy_ps = 0;          // their frames' time on TXD, start bit to end of stop bit
    TimePs rx_line_busy_ps = 0;          // the frames of the bytes in the RX log on RXD, start bit to end of stop bit
    std::int64_t tx_overflow_bytes = 0;  // host bytes dropped because the TX FIFO was full
    std::int64_t rx_overflow_bytes = 0;  // received bytes dropped because the RX FIFO was full
    std::int64_t framing_errors = 0;     // frames dropped for a low stop bit (or a parity error)
    std::int64_t false_starts = 0;       // start bits that were high again at their middle (glitches)
    // USB frames with data that a latency spike delayed (Cp2102Config::usb_spikes), and the delay each direction's
    // data took from them (a frame held up behind a delayed one counts its own spike only).
    std::int64_t usb_spikes_out = 0;
    std::int64_t usb_spikes_in = 0;
    TimePs usb_spike_delay_out_ps = 0;
    TimePs usb_spike_delay_in_ps = 0;
};

class Cp2102 : public sc_core::sc_module {
public:
    sc_core::sc_out<bool> txd;  // to the target's RX pin (idles high)
    sc_core::sc_in<bool> rxd;   // from the target's TX pin

    struct TxByte {
        std::uint8_t byte;
        TimePs t_write_ps;      // host called usb_write
        TimePs t_usb_ps;        // the USB frame that carried it to the chip
        TimePs t_start_bit_ps;  // start bit on TXD
        TimePs t_stop_end_ps;   // end of the stop bit
    };
    struct RxByte {
        std::uint8_t byte;
        TimePs t_start_bit_ps;
        TimePs t_stop_end_ps;
        TimePs t_host_visible_ps;  // -1 when the byte never reaches the host (framing error, FIFO overflow)
        bool framing_error;
    };

    Cp2102(const sc_core::sc_module_name& name, const Cp2102Config& cfg);

    // Host (USB) side, called from a host SC_THREAD at the current simulation time.
    // Bulk OUT: the bytes reach the chip at the next USB frame start (>= now) and queue in the TX FIFO. A byte
    // that finds the FIFO full is dropped and counted: a real driver would block instead (the chip NAKs the
    // OUT packet), but the senders modelled here never have more than one packet in flight, so a drop flags
    // a sender bug rather than hiding it. One frame carries up to 19 x 64 bytes (USB 2.0 §5.8.4), more than
    // the FIFO holds, so any write that fits arrives in a single frame.
    void usb_write(const std::uint8_t* data, std::size_t n);
    void usb_write(const std::vector<std::uint8_t>& data) { usb_write(data.data(), data.size()); }
    [[nodiscard]] std::size_t in_waiting() const { return m_host_rx.size(); }  // bytes the host driver holds
    std::optional<std::uint8_t> read_byte();
    // pyserial reset_input_buffer(): drops what the host driver holds now. Bytes still in the chip or in
    // transit (visible time in the future) arrive later, as on a real port.
    void reset_input_buffer() { m_host_rx.clear(); }
    [[nodiscard]] const sc_core::sc_event& data_event() const { return m_data_ev; }
    // The earliest time TXD may change, asked at the current time (>= now): the next edge of the frames being sent,
    // else the next USB frame start (host bytes reach the chip only there). A clocked model of the target may run
    // ahead to it. At the instant of an edge it is now: the edge written is seen on TXD a delta later.
    [[nodiscard]] TimePs txd_quiet_until() const;

    // Keeps in tx_log() only the bytes sent at indices first, first + stride, ... (counted over every byte sent,
    // as Cp2102Stats::tx_bytes): a reader that needs one byte per packet (fpga-uart's dead-time split reads each
    // packet's first) keeps a long job's log short. Call before the simulation starts.
    void thin_tx_log(std::size_t first, std::size_t stride) {
        m_tx_log_first = first;
        m_tx_log_stride = stride;
    }
    // Every byte logged, numbered over the whole run (size() counts the dropped ones too).
    [[nodiscard]] const RecordLog<TxByte>& tx_log() const { return m_tx_log; }
    [[nodiscard]] const RecordLog<RxByte>& rx_log() const { return m_rx_log; }
    // The reader has read the bytes before index `end`: they go.
    void drop_tx_log_before(std::size_t end) { m_tx_log.drop_before(end); }
    void drop_rx_log_before(std::size_t end) { m_rx_log.drop_before(end); }
    [[nodiscard]] const Cp2102Baud& baud() const { return m_baud; }
    [[nodiscard]] const Cp2102Stats& stats() const { return m_stats; }

private:
    struct UsbOutByte {
        std::uint8_t byte;
        TimePs t_write_ps;
        TimePs t_usb_ps;
    };
    struct UsbInByte {
        std::uint8_t byte;
        TimePs t_usb_ps;      // leaves the chip's RX FIFO
        TimePs t_visible_ps;  // reaches the host application
    };

    void usb_out_arrival();  // SC_METHOD: USB frame delivers host bytes into the TX FIFO
    void tx_thread();        // SC_THREAD: serialises the TX FIFO on txd, one wake per line edge
    void on_rxd();           // SC_METHOD: rxd transitions
    void rx_decide();        // SC_METHOD: the receiver's decision at the last stop-bit sample
    void rx_deliver();       // SC_METHOD: received bytes become visible to the host
    void wait_until(TimePs t_ps);
    void log_rx(const RxByte& b);
    // One direction of the USB link with its latency spikes (Cp2102Config::usb_spikes).
    struct SpikedPipe {
        UsbSpikeDraw draw;
        TimePs last_ps = 0;            // the last data's arrival at the pipe's end
        std::int64_t last_frame = -1;  // the USB frame that carried it
    };
    // The time the data of the USB frame starting at t_frame_ps, due at t_due_ps, reaches the pipe's end, its spike
    // included, never before the data of an earlier frame (a bulk pipe keeps its order); counts the frame's spike
    // once, in `spikes` and `delay_ps`.
    TimePs spiked(SpikedPipe& pipe, TimePs t_frame_ps, TimePs t_due_ps, std::int64_t& spikes, TimePs& delay_ps);

    Cp2102Config m_cfg;
    Cp2102Baud m_baud;
    BitClock m_clk;
    SpikedPipe m_out;  // host to chip
    SpikedPipe m_in;   // chip to host

    std::deque<UsbOutByte> m_usb_out;  // written by the host, not yet at the chip
    std::deque<UsbOutByte> m_tx_fifo;
    bool m_tx_sending = false;
    TimePs m_txd_next_ps = 0;      // while sending: the next TXD edge (or the end of the last stop bit)
    TimePs m_txd_written_ps = -1;  // the last TXD edge written
    sc_core::sc_event m_usb_out_ev;
    sc_core::sc_event m_tx_fifo_ev;

    bool m_rx_busy = false;
    TimePs m_rx_fall_ps = 0;
    EdgeLog m_rx_line;               // rxd transitions of the frame being received
    std::deque<UsbInByte> m_usb_in;  // received, not yet visible to the host (in the chip or in transit)
    std::deque<std::uint8_t> m_host_rx;
    sc_core::sc_event m_rx_decide_ev;
    sc_core::sc_event m_rx_deliver_ev;
    sc_core::sc_event m_data_ev;

    RecordLog<TxByte> m_tx_log;
    std::size_t m_tx_log_first = 0;
    std::size_t m_tx_log_stride = 1;  // every byte
    RecordLog<RxByte> m_rx_log;
    Cp2102Stats m_stats;
};

}  // namespace cnc::uart
