// The USART's I/O registers on both MCUs (McuMap::usart), on the one UsartUnit: USART0 of the ATmega328P (datasheet
// §20.11) and the ATmega16's USART (doc2466 "USART Register Description"). Their bits are the same; the ATmega16's
// UCSRC and UBRRH share one I/O address ("Accessing UBRRH/UCSRC Registers"):
//   * a write with URSEL (bit 7) = 1 goes to UCSRC, with URSEL = 0 to UBRRH;
//   * a read returns UBRRH (URSEL reads 0), unless the same address was read in the previous clock cycle: then
//     UCSRC (URSEL reads 1). Two `in` instructions back to back read UBRRH, then UCSRC.
#include "avr/atmega16_regs.hpp"
#include "avr/avr_chip.hpp"

#include <sim_avr.h>

namespace cnc::avr {

bool AvrChip::write_usart_reg(std::uint16_t addr, std::uint8_t v) {
    const UsartRegs& r = m_map.usart;
    const Cycle c = now();
    std::uint8_t* data = m_avr->data;
    if (addr == r.udr) {
        m_usart.write_udr(c, v);
    } else if (addr == r.ucsra) {
        m_usart.write_ucsra(c, v);
    } else if (addr == r.ucsrb) {  // the interrupt enables must be in place when the unit re-raises its flags
        data[addr] = v;
        m_usart.write_ucsrb(c, v);
        data[addr] = m_usart.ucsrb();
    } else if (addr == r.ubrrl) {
        m_usart.write_ubrrl(c, v);
        data[addr] = v;
    } else if (r.shared_ucsrc() && addr == r.ucsrc) {
        if ((v & reg16::kUrsel) != 0)
            m_usart.write_ucsrc(c, static_cast<std::uint8_t>(v & ~reg16::kUrsel));
        else
            m_usart.write_ubrrh(c, v);
    } else if (addr == r.ucsrc) {
        m_usart.write_ucsrc(c, v);
        data[addr] = v;
    } else if (addr == r.ubrrh) {
        m_usart.write_ubrrh(c, v);
        data[addr] = m_usart.ubrrh();
    } else {
        return false;
    }
    return true;
}

std::optional<std::uint8_t> AvrChip::read_usart_reg(std::uint16_t addr) {
    const UsartRegs& r = m_map.usart;
    const Cycle c = now();
    if (addr == r.ucsra) {
        m_usart.advance_to(c);
        return m_usart.ucsra();
    }
    if (addr == r.udr) {
        const std::uint8_t v = m_usart.read_udr(c);
        reschedule();
        return v;
    }
    if (r.shared_ucsrc() && addr == r.ucsrc) {
        const bool second = m_shared_read_cycle && *m_shared_read_cycle + 1 == c;
        m_shared_read_cycle = c;
        return second ? static_cast<std::uint8_t>(m_usart.ucsrc() | reg16::kUrsel) : m_usart.ubrrh();
    }
    return std::nullopt;
}

}  // namespace cnc::avr
