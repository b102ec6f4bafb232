// USART0 of the ATmega328P in asynchronous mode (datasheet §20), at line level and cycle-exact.
//
// Baud rate (§20.3.1, Table 20-1): one bit lasts 16*(UBRR0+1) cycles, 8*(UBRR0+1) with U2X0 (UBRR0 = 16,
// U2X0 = 0: 272 cycles, 58 823.5 Bd). The baud rate generator is a free-running down-counter restarted by a
// write to UBRR0L, so the transmitter's bit clock ticks at cycles w + k*bit_cycles after the last UBRR0L write w.
//
// Transmitter (§20.6): UDR0 is written into the transmit buffer (UDRE0 falls). The shift register loads the
// buffer at the next bit-clock tick when it is idle (decision: the datasheet only says "when it is idle", and the
// transmitter is clocked by the bit clock), or at the end of the last stop bit when it is busy, so frames follow
// each other with no gap. Loading starts the start bit and sets UDRE0 again. A frame is 1 start + 5..8 data
// (+ parity) + 1..2 stop bits: 10 bit times for 8N1, 2720 cycles at UBRR0 = 16 (not simavr's 11). TXC0 is set at
// the end of the last stop bit when no new data is in the buffer. A write to UDR0 while UDRE0 = 0, or while the
// transmitter is disabled, is ignored (§20.6.1 / decision) and counted.
//
// Receiver (§20.7): frames are decoded outside (the line receiver samples mid-bit at this USART's bit clock) and
// handed in with their start and decision cycles; RXC0 and the byte appear at the decision cycle (the middle
// of the stop bit; the silicon takes its 3 majority samples at 8/16, 9/16 and 10/16 of each bit, 16x
// oversampled, so it decides about 1/16 bit after the middle). The receive buffer holds two bytes with their
// FE0/DOR0/UPE0 flags; a frame that completes with the buffer full is lost and DOR0 is set on the buffer's last
// byte. Frames that start while RXEN0 = 0 are lost. 9-bit frames (UCSZ0 = 111) are not modelled (sent as 8-bit).
#pragma once
#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

#include "avr/core/prescaler.hpp"
#include "uart/core/line_receiver.hpp"
#include "uart/core/uart_frame.hpp"

namespace cnc::avr {

class UsartSink {
public:
    virtual ~UsartSink() = default;
    virtual void usart_flags(Cycle c) = 0;            // RXC0 / TXC0 / UDRE0 may have changed
    virtual void usart_txd(Cycle c, bool level) = 0;  // the TXD line changed
};

struct UsartStats {
    std::int64_t tx_frames = 0;
    std::int64_t tx_ignored_writes = 0;  // UDR0 written while UDRE0 = 0 or TXEN0 = 0
    std::int64_t rx_frames = 0;          // frames that reached the receive buffer (including those with FE0/UPE0)
    std::int64_t rx_framing_errors = 0;  // of those, stop bit sampled low (FE0 set)
    std::int64_t rx_parity_errors = 0;
    std::int64_t rx_lost_disabled = 0;  // frames that started while RXEN0 = 0
    std::int64_t rx_overruns = 0;       // frames lost to a full receive buffer (DOR0)
};

struct UsartTxRecord {
    std::uint8_t byte = 0;
    Cycle write_cycle = 0;  // UDR0 written
    Cycle start_cycle = 0;  // start bit begins (shift register loaded, UDRE0 set)
    Cycle end_cycle = 0;    // last stop bit ends (TXC0 set if nothing follows)
};

struct UsartRxRecord {
    std::uint8_t byte = 0;
    Cycle start_cycle = 0;
    Cycle decision_cycle = 0;  // RXC0 set
    uart::RxStatus status = uart::RxStatus::Ok;
    bool stored = false;  // reached the receive buffer
};

class UsartUnit {
public:
    // keep_logs: tx_log() and rx_log() record every byte (AvrCoreConfig::keep_usart_logs); otherwise they stay empty.
    UsartUnit(UsartSink& sink, bool keep_logs);

    void write_udr(Cycle c, std::uint8_t v);
    std::uint8_t read_udr(Cycle c);
    void write_ucsra(Cycle c, std::uint8_t v);
    void write_ucsrb(Cycle c, std::uint8_t v);
    void write_ucsrc(Cycle c, std::uint8_t v);
    void write_ubrrl(Cycle c, std::uint8_t v);
    void write_ubrrh(Cycle c, std::uint8_t v);
    [[nodiscard]] std::uint8_t ucsra() const;
    [[nodiscard]] std::uint8_t ucsrb() const { return m_ucsrb; }
    [[nodiscard]] std::uint8_t ucsrc() const { return m_ucsrc; }
    [[nodiscard]] std::uint8_t ubrrl() const { return static_cast<std::uint8_t>(m_ubrr & 0xFF); }
    [[nodiscard]] std::uint8_t ubrrh() const { return static_cast<std::uint8_t>(m_ubrr >> 8); }

    // The TX-complete interrupt was taken: the hardware clears TXC0 (§20.6.3).
    void clear_txc(Cycle c);

    // A frame decoded at this USART's bit clock, whose start edge was at cycle `start` and whose decision is at
    // cycle `decision` (the caller has advanced the unit to at least `decision`).
    void receive(Cycle start, Cycle decision, const uart::RxFrame& frame);

    void advance_to(Cycle c);
    [[nodiscard]] std::optional<Cycle> next_event() const;

    [[nodiscard]] std::int64_t bit_cycles() const;
    [[nodiscard]] uart::BitClock bit_clock(std::int64_t f_cpu_hz) const { return {bit_cycles(), f_cpu_hz}; }
    [[nodiscard]] uart::FrameFormat format() const;
    [[nodiscard]] bool rx_enabled_at(Cycle c) const;
    [[nodiscard]] bool rxc() const { return !m_rx_buffer.empty(); }
    [[nodiscard]] bool udre() const { return !m_tx_buffer.has_value(); }
    [[nodiscard]] bool txc() const { return m_txc; }
    [[nodiscard]] bool txd() const { return m_txd; }
    [[nodiscard]] const UsartStats& stats() const { return m_stats; }
    [[nodiscard]] const std::vector<UsartTxRecord>& tx_log() const { return m_tx_log; }
    [[nodiscard]] const std::vector<UsartRxRecord>& rx_log() const { return m_rx_log; }

private:
    struct RxEntry {
        std::uint8_t byte;
        bool fe;
        bool dor;
        bool upe;
    };
    struct Shift {
        std::vector<bool> bits;  // bit k is on the line during [start + k*bit, start + (k+1)*bit)
        Cycle start = 0;
        std::int64_t bit = 1;
        std::size_t next = 1;                  // next bit boundary to process (bits.size() = end of the frame)
        std::optional<std::size_t> log_index;  // none when the logs are not kept
    };
    [[nodiscard]] bool tx_enabled() const;
    [[nodiscard]] Cycle next_bit_tick_after(Cycle c) const;
    void load(Cycle c);
    void set_txd(Cycle c, bool level);

    UsartSink& m_sink;
    const bool m_keep_logs;
    std::uint8_t m_ucsra_rw = 0;  // U2X0, MPCM0
    std::uint8_t m_ucsrb = 0;
    std::uint8_t m_ucsrc = 0x06;  // reset value: 8N1 (§20.11.4)
    std::uint16_t m_ubrr = 0;
    Cycle m_baud_origin = 0;  // last UBRR0L write (power-on: cycle 0)
    struct TxBuffered {
        std::uint8_t byte;
        std::optional<std::size_t> log_index;
    };
    std::optional<TxBuffered> m_tx_buffer;
    std::optional<Cycle> m_load_at;  // the idle shift register loads the buffer at this bit-clock tick
    std::optional<Shift> m_shift;
    bool m_txc = false;
    bool m_txd = true;
    std::deque<RxEntry> m_rx_buffer;
    std::vector<std::pair<Cycle, bool>> m_rxen_changes{{0, false}};
    UsartStats m_stats;
    std::vector<UsartTxRecord> m_tx_log;
    std::vector<UsartRxRecord> m_rx_log;
};

}  // namespace cnc::avr
