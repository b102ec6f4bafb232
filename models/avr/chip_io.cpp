// The I/O registers of Timer0/1/2, the prescalers and the ports, as the AVR core reads and writes them (the USART's:
// chip_io_usart.cpp).
#include <cstdio>

#include "avr/atmega328p_regs.hpp"
#include "avr/avr_chip.hpp"

#include <sim_avr.h>
#include <sim_interrupts.h>
#include <sim_regbit.h>

namespace cnc::avr {

using namespace reg;

namespace {

// ATmega328P: TIFR0..2 and TIMSK0..2 are consecutive: the timer a flag or mask register belongs to.
int timer_of(std::uint16_t flag_or_mask_reg) {
    return flag_or_mask_reg >= kTimsk0 ? flag_or_mask_reg - kTimsk0 : flag_or_mask_reg - kTifr0;
}

}  // namespace

int AvrChip::flag_bit_vector(std::uint16_t addr, int bit) const {
    const auto flag = timer_flag_bit(m_map.mcu, m_map.mcu == Mcu::Atmega328p ? timer_of(addr) : 0, bit);
    return flag ? timer_vector(flag->first, flag->second) : 0;
}

std::uint8_t AvrChip::latch_high(std::uint16_t v) {
    m_temp16 = static_cast<std::uint8_t>(v >> 8);
    return static_cast<std::uint8_t>(v);
}

void AvrChip::write_timer1_low(Timer1Reg r, std::uint16_t low_addr, std::uint8_t low) {
    const Cycle c = now();
    TimerUnit& t1 = *m_timers[1];
    const auto word = static_cast<std::uint16_t>((m_temp16 << 8) | low);
    switch (r) {
        case Timer1Reg::Tcnt:
            t1.write_tcnt(c, word);
            return;
        case Timer1Reg::Icr:
            t1.write_icr(c, word);
            return;
        case Timer1Reg::OcrA:
        case Timer1Reg::OcrB:
            t1.write_ocr(c, r == Timer1Reg::OcrA ? Channel::A : Channel::B, word);
            m_avr->data[low_addr] = low;  // OCR1xH is the next address on both MCUs
            m_avr->data[low_addr + 1] = m_temp16;
            return;
    }
}

bool AvrChip::write_shared_timer_reg(std::uint16_t addr, std::uint8_t v) {
    const TimerRegs& r = m_map.timer_regs;
    const Cycle c = now();
    // §16.3 (328P), "Accessing 16-bit Registers" (ATmega16): a high byte write goes to TEMP; the low byte write
    // moves TEMP:low into the register at once.
    if (addr == r.tcnt1l + 1 || addr == r.icr1l + 1 || addr == r.ocr1al + 1 || addr == r.ocr1bl + 1) {
        m_temp16 = v;
    } else if (addr == r.tcnt1l) {
        write_timer1_low(Timer1Reg::Tcnt, addr, v);
    } else if (addr == r.icr1l) {
        write_timer1_low(Timer1Reg::Icr, addr, v);
    } else if (addr == r.ocr1al) {
        write_timer1_low(Timer1Reg::OcrA, addr, v);
    } else if (addr == r.ocr1bl) {
        write_timer1_low(Timer1Reg::OcrB, addr, v);
    } else if (addr == r.tcnt0) {
        m_timers[0]->write_tcnt(c, v);
    } else if (addr == r.tcnt2) {
        m_timers[2]->write_tcnt(c, v);
    } else if (addr == r.assr) {
        if ((v & r.assr_as2) != 0 && (m_avr->data[addr] & r.assr_as2) == 0)
            std::fprintf(stderr,
                         "avr: ASSR.AS2 set: Timer2's asynchronous mode is not modelled (it keeps counting the I/O "
                         "clock)\n");
        m_avr->data[addr] = static_cast<std::uint8_t>(v & r.assr_writable);
    } else {
        return false;
    }
    return true;
}

std::optional<std::uint8_t> AvrChip::read_shared_timer_reg(std::uint16_t addr) {
    const TimerRegs& r = m_map.timer_regs;
    const Cycle c = now();
    if (addr == r.tcnt0) return static_cast<std::uint8_t>(m_timers[0]->read_tcnt(c));
    if (addr == r.tcnt2) return static_cast<std::uint8_t>(m_timers[2]->read_tcnt(c));
    // Reading the low byte copies the high byte into TEMP, which the high byte read returns.
    if (addr == r.tcnt1l) return latch_high(m_timers[1]->read_tcnt(c));
    if (addr == r.icr1l) return latch_high(m_timers[1]->icr());
    if (addr == r.tcnt1l + 1 || addr == r.icr1l + 1) return m_temp16;
    return std::nullopt;
}

std::optional<int> AvrChip::single_bit_instruction(std::uint16_t addr, bool* set) const {
    // SBI A,b = 1001 1010 AAAA Abbb, CBI A,b = 1001 1000 AAAA Abbb (AVR instruction set manual).
    const std::uint32_t pc = m_avr->pc;
    const std::uint16_t op = static_cast<std::uint16_t>(m_avr->flash[pc] | (m_avr->flash[pc + 1] << 8));
    const std::uint16_t kind = op & 0xFF00;
    if (kind != 0x9A00 && kind != 0x9800) return std::nullopt;
    if (((op >> 3) & 0x1F) + 0x20 != addr) return std::nullopt;
    *set = kind == 0x9A00;
    return op & 7;
}

void AvrChip::io_write(std::uint16_t addr, std::uint8_t v) {
    if (m_map.mcu == Mcu::Atmega16) {
        io_write_atmega16(addr, v);
        reschedule();
        return;
    }
    const Cycle c = now();
    std::uint8_t* data = m_avr->data;
    TimerUnit& t0 = *m_timers[0];
    TimerUnit& t1 = *m_timers[1];
    TimerUnit& t2 = *m_timers[2];
    switch (addr) {
        case kTifr0:
        case kTifr1:
        case kTifr2:
            write_timer_flags(addr, v);
            break;
        case kTimsk0:
        case kTimsk1:
        case kTimsk2:
            write_timsk(addr, v);
            break;
        case kGtccr:
            write_gtccr(v);
            break;
        case kTccr0a:
            t0.write_tccra(c, v);
            data[addr] = v;
            break;
        case kTccr0b:
            t0.write_tccrb(c, v);
            data[addr] = t0.tccrb();
            break;
        case kOcr0a:
            t0.write_ocr(c, Channel::A, v);
            data[addr] = v;
            break;
        case kOcr0b:
            t0.write_ocr(c, Channel::B, v);
            data[addr] = v;
            break;
        case kTccr1a:
            t1.write_tccra(c, v);
            data[addr] = v;
            break;
        case kTccr1b:
            t1.write_tccrb(c, v);
            data[addr] = t1.tccrb();
            break;
        case kTccr1c:
            t1.write_tccrc(c, v);
            data[addr] = 0;
            break;
        case kTccr2a:
            t2.write_tccra(c, v);
            data[addr] = v;
            break;
        case kTccr2b:
            t2.write_tccrb(c, v);
            data[addr] = t2.tccrb();
            break;
        case kOcr2a:
            t2.write_ocr(c, Channel::A, v);
            data[addr] = v;
            break;
        case kOcr2b:
            t2.write_ocr(c, Channel::B, v);
            data[addr] = v;
            break;
        default:
            if (!write_shared_timer_reg(addr, v) && !write_usart_reg(addr, v) && port_reg_index(addr))
                port_write(addr, v);
            break;
    }
    reschedule();
}

std::uint8_t AvrChip::io_read(std::uint16_t addr) {
    if (const auto v = read_shared_timer_reg(addr)) return *v;
    if (const auto v = read_usart_reg(addr)) return *v;
    return port_read(addr);
}

void AvrChip::write_timer_flags(std::uint16_t addr, std::uint8_t v) {
    m_quiet_flags_stale = true;
    // A flag is cleared by writing a one to it; SBI/CBI act on their one bit only.
    bool set = false;
    if (const auto bit = single_bit_instruction(addr, &set)) v = set ? static_cast<std::uint8_t>(1U << *bit) : 0;
    for (int bit = 0; bit < 8; ++bit) {
        const int n = flag_bit_vector(addr, bit);
        if (((v >> bit) & 1U) == 0 || n == 0) continue;
        avr_int_vector_t* vec = m_vectors[static_cast<std::size_t>(n)];
        if (avr_regbit_get(m_avr, vec->raised) != 0) avr_clear_interrupt(m_avr, vec);
    }
}

void AvrChip::write_timsk(std::uint16_t addr, std::uint8_t v) {
    m_quiet_flags_stale = true;
    m_avr->data[addr] = v;
    // simavr queues an interrupt only when its flag is raised while enabled: enabling one whose flag is already
    // set must fire it now, as on silicon.
    for (int bit = 0; bit < 8; ++bit) {
        const int n = flag_bit_vector(addr, bit);
        if (((v >> bit) & 1U) == 0 || n == 0) continue;
        avr_int_vector_t* vec = m_vectors[static_cast<std::size_t>(n)];
        if (avr_regbit_get(m_avr, vec->raised) != 0 && vec->pending == 0) avr_raise_interrupt(m_avr, vec);
    }
}

void AvrChip::write_gtccr(std::uint8_t v) {
    const Cycle c = now();
    for (auto& t : m_timers) t->advance_to(c);
    const bool tsm = (v & kTsm) != 0;
    const auto apply = [&](Prescaler& p, bool reset_bit) {
        if (reset_bit && tsm)
            p.hold(c);  // §17.4.1: TSM keeps the written PSR bit, holding the reset
        else if (reset_bit)
            p.restart(c);
        else
            p.release(c);
    };
    apply(m_prescaler01, (v & kPsrsync) != 0);
    apply(m_prescaler2, (v & kPsrasy) != 0);
    // Without TSM the PSR bits clear at once; with it they read back as written.
    m_avr->data[kGtccr] = tsm ? static_cast<std::uint8_t>(v & (kTsm | kPsrasy | kPsrsync)) : 0;
}

}  // namespace cnc::avr
