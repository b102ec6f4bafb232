#include "avr/core/usart_unit.hpp"

#include <algorithm>

namespace cnc::avr {

namespace {

// Datasheet §20.11 register bits.
constexpr std::uint8_t kRxc = 0x80;   // UCSR0A.RXC0
constexpr std::uint8_t kTxc = 0x40;   // UCSR0A.TXC0
constexpr std::uint8_t kUdre = 0x20;  // UCSR0A.UDRE0
constexpr std::uint8_t kFe = 0x10;    // UCSR0A.FE0
constexpr std::uint8_t kDor = 0x08;   // UCSR0A.DOR0
constexpr std::uint8_t kUpe = 0x04;   // UCSR0A.UPE0
constexpr std::uint8_t kU2x = 0x02;   // UCSR0A.U2X0
constexpr std::uint8_t kMpcm = 0x01;  // UCSR0A.MPCM0
constexpr std::uint8_t kRxen = 0x10;  // UCSR0B.RXEN0
constexpr std::uint8_t kTxen = 0x08;  // UCSR0B.TXEN0
constexpr std::uint8_t kRxb8 = 0x02;  // UCSR0B.RXB80 (read only)

}  // namespace

UsartUnit::UsartUnit(UsartSink& sink, bool keep_logs) : m_sink(sink), m_keep_logs(keep_logs) {}

std::int64_t UsartUnit::bit_cycles() const {
    return ((m_ucsra_rw & kU2x) != 0 ? 8 : 16) * (static_cast<std::int64_t>(m_ubrr) + 1);  // Table 20-1
}

uart::FrameFormat UsartUnit::format() const {
    uart::FrameFormat f;
    const unsigned ucsz = (m_ucsrc >> 1) & 3U;  // UCSZ01:00; UCSZ02 (9-bit) is not modelled
    f.data_bits = 5 + static_cast<int>(ucsz);
    const unsigned upm = (m_ucsrc >> 4) & 3U;  // Table 20-9: 10 even, 11 odd, 01 reserved
    f.parity = upm == 2 ? uart::Parity::Even : upm == 3 ? uart::Parity::Odd : uart::Parity::None;
    f.stop_bits = (m_ucsrc & 0x08U) != 0 ? 2 : 1;  // USBS0
    return f;
}

bool UsartUnit::tx_enabled() const {
    return (m_ucsrb & kTxen) != 0;
}

bool UsartUnit::rx_enabled_at(Cycle c) const {
    bool on = false;
    for (const auto& [t, en] : m_rxen_changes) {
        if (t > c) break;
        on = en;
    }
    return on;
}

std::uint8_t UsartUnit::ucsra() const {
    std::uint8_t v = m_ucsra_rw;
    if (rxc()) v |= kRxc;
    if (m_txc) v |= kTxc;
    if (udre()) v |= kUdre;
    if (!m_rx_buffer.empty()) {
        const RxEntry& e = m_rx_buffer.front();
        if (e.fe) v |= kFe;
        if (e.dor) v |= kDor;
        if (e.upe) v |= kUpe;
    }
    return v;
}

Cycle UsartUnit::next_bit_tick_after(Cycle c) const {
    const std::int64_t bit = bit_cycles();
    return m_baud_origin + ((c - m_baud_origin) / bit + 1) * bit;
}

void UsartUnit::set_txd(Cycle c, bool level) {
    if (level == m_txd) return;
    m_txd = level;
    m_sink.usart_txd(c, level);
}

void UsartUnit::load(Cycle c) {
    Shift s;
    s.bits = uart::frame_bits(m_tx_buffer->byte, format());
    s.start = c;
    s.bit = bit_cycles();
    s.log_index = m_tx_buffer->log_index;
    if (s.log_index) m_tx_log[*s.log_index].start_cycle = c;
    m_tx_buffer.reset();
    m_load_at.reset();
    m_shift = s;
    set_txd(c, false);      // start bit
    m_sink.usart_flags(c);  // UDRE0 set again
}

std::optional<Cycle> UsartUnit::next_event() const {
    if (m_shift) return m_shift->start + static_cast<Cycle>(m_shift->next) * m_shift->bit;
    return m_load_at;
}

void UsartUnit::advance_to(Cycle c) {
    for (auto t = next_event(); t && *t <= c; t = next_event()) {
        if (!m_shift) {
            load(*t);
            continue;
        }
        Shift& s = *m_shift;
        if (s.next < s.bits.size()) {
            set_txd(*t, s.bits[s.next]);
            ++s.next;
            continue;
        }
        if (s.log_index) m_tx_log[*s.log_index].end_cycle = *t;
        ++m_stats.tx_frames;
        m_shift.reset();
        if (m_tx_buffer) {
            load(*t);  // back to back: the next start bit follows the stop bit
        } else {
            m_txc = true;
            m_sink.usart_flags(*t);
        }
    }
}

void UsartUnit::write_udr(Cycle c, std::uint8_t v) {
    advance_to(c);
    if (!udre() || !tx_enabled()) {
        ++m_stats.tx_ignored_writes;
        return;
    }
    m_tx_buffer = TxBuffered{v, std::nullopt};
    if (m_keep_logs) {
        m_tx_buffer->log_index = m_tx_log.size();
        m_tx_log.push_back({v, c, -1, -1});
    }
    if (!m_shift) m_load_at = next_bit_tick_after(c);
    m_sink.usart_flags(c);
}

std::uint8_t UsartUnit::read_udr(Cycle c) {
    advance_to(c);
    if (m_rx_buffer.empty()) return 0;
    const std::uint8_t b = m_rx_buffer.front().byte;
    m_rx_buffer.pop_front();
    m_sink.usart_flags(c);
    return b;
}

void UsartUnit::write_ucsra(Cycle c, std::uint8_t v) {
    advance_to(c);
    m_ucsra_rw = static_cast<std::uint8_t>(v & (kU2x | kMpcm));
    if ((v & kTxc) != 0 && m_txc) {  // TXC0 is cleared by writing a one to it
        m_txc = false;
        m_sink.usart_flags(c);
    }
}

void UsartUnit::clear_txc(Cycle c) {
    if (!m_txc) return;
    m_txc = false;
    m_sink.usart_flags(c);
}

void UsartUnit::write_ucsrb(Cycle c, std::uint8_t v) {
    advance_to(c);
    const bool rx_was = (m_ucsrb & kRxen) != 0;
    m_ucsrb = static_cast<std::uint8_t>((v & ~kRxb8) | (m_ucsrb & kRxb8));
    const bool rx_now = (m_ucsrb & kRxen) != 0;
    if (rx_was != rx_now) {
        m_rxen_changes.emplace_back(c, rx_now);
        if (!rx_now) m_rx_buffer.clear();  // §20.7.5: disabling the receiver flushes the receive buffer
    }
    // §20.6.5: clearing TXEN0 takes effect only when the ongoing and pending transmissions have completed.
    m_sink.usart_flags(c);  // the interrupt enables may have changed
}

void UsartUnit::write_ucsrc(Cycle c, std::uint8_t v) {
    advance_to(c);
    m_ucsrc = v;
}

void UsartUnit::write_ubrrl(Cycle c, std::uint8_t v) {
    advance_to(c);
    m_ubrr = static_cast<std::uint16_t>((m_ubrr & 0x0F00) | v);
    m_baud_origin = c;  // §20.11.5: writing UBRR0L restarts the baud rate prescaler
    if (m_load_at) m_load_at = next_bit_tick_after(c);
}

void UsartUnit::write_ubrrh(Cycle c, std::uint8_t v) {
    advance_to(c);
    m_ubrr = static_cast<std::uint16_t>(((v & 0x0FU) << 8) | (m_ubrr & 0xFF));
}

void UsartUnit::receive(Cycle start, Cycle decision, const uart::RxFrame& frame) {
    advance_to(decision);
    UsartRxRecord rec{frame.byte, start, decision, frame.status, false};
    if (frame.status == uart::RxStatus::FalseStart) {
        if (m_keep_logs) m_rx_log.push_back(rec);
        return;
    }
    if (!rx_enabled_at(start) || !rx_enabled_at(decision)) {
        ++m_stats.rx_lost_disabled;
    } else if (m_rx_buffer.size() >= 2) {  // §20.7.4: two-byte receive buffer
        ++m_stats.rx_overruns;
        m_rx_buffer.back().dor = true;
    } else {
        const bool fe = frame.status == uart::RxStatus::FramingError;
        const bool upe = frame.status == uart::RxStatus::ParityError;
        m_rx_buffer.push_back({frame.byte, fe, false, upe});
        ++m_stats.rx_frames;
        if (fe) ++m_stats.rx_framing_errors;
        if (upe) ++m_stats.rx_parity_errors;
        rec.stored = true;
        m_sink.usart_flags(decision);
    }
    if (m_keep_logs) m_rx_log.push_back(rec);
}

}  // namespace cnc::avr
