// The ATmega16's Timer0/1/2 and prescaler registers (datasheet doc2466 §"8-bit Timer/Counter0", "16-bit
// Timer/Counter1", "8-bit Timer/Counter2", "Timer/Counter0 and Timer/Counter1 Prescalers") on the same TimerUnit
// models as the ATmega328P's: the layouts differ, the counters do not. The registers that differ only in address
// (counters, Timer1's 16-bit registers, ASSR) go through the shared handlers of chip_io.cpp and McuMap::timer_regs.
//   * TCCR0 / TCCR2 = FOCn (7), WGMn0 (6), COMn1:0 (5:4), WGMn1 (3), CSn2:0 (2:0), with one compare unit (OCR0 /
//     OCR2, channel A here). Modes WGMn1:0 = 0 normal, 1 phase correct PWM, 2 CTC, 3 fast PWM: the 328P's modes
//     0..3, so the bits are moved to the TCCRnA/TCCRnB places TimerUnit decodes.
//   * TCCR1A carries FOC1A/FOC1B (bits 3:2), which the 328P has in TCCR1C.
//   * SFIOR.PSR10 / PSR2 reset the Timer0/1 and the Timer2 prescalers (no TSM: they clear at once).
//   * INT0 (PD2) and INT1 (PD3), "External Interrupts": MCUCR ISCn1:0 = 00 low level (the interrupt repeats while
//     the pin is low), 01 any change, 10 falling edge, 11 rising edge; INTFn in GIFR is set by the edge (and
//     cleared by writing a one to it, or when the vector runs), GICR.INTn enables it.
#include <cstdio>

#include "avr/atmega16_regs.hpp"
#include "avr/avr_chip.hpp"

#include <sim_avr.h>
#include <sim_interrupts.h>
#include <sim_regbit.h>

namespace cnc::avr {

using namespace reg16;

namespace {

// TCCR0/TCCR2 -> the 328P's TCCRnA (COMnA1:0 at 7:6, WGMn1:0 at 1:0) and TCCRnB (FOCnA at 7, CS at 2:0).
std::uint8_t tccra_of(std::uint8_t v) {
    const unsigned com = (v >> 4) & 3U;
    const unsigned wgm = ((v >> 6) & 1U) | (((v >> 3) & 1U) << 1);
    return static_cast<std::uint8_t>((com << 6) | wgm);
}

std::uint8_t tccrb_of(std::uint8_t v) {
    return static_cast<std::uint8_t>((v & 0x80U) | (v & 7U));
}

}  // namespace

void AvrChip::install_atmega16_hooks(const std::function<void(std::uint16_t)>& take_write,
                                     const std::function<void(std::uint16_t)>& take_read) {
    for (const std::uint16_t a :
         {kMcucr,  kGicr,   kGifr,   kOcr0,   kTimsk,  kTifr,  kTccr0, kTcnt0, kSfior, kTccr1a, kTccr1b, kTcnt1h,
          kTcnt1l, kOcr1ah, kOcr1al, kOcr1bh, kOcr1bl, kIcr1h, kIcr1l, kTccr2, kTcnt2, kOcr2,   kAssr})
        take_write(a);
    for (const std::uint16_t a : {kTcnt0, kTcnt1l, kTcnt1h, kIcr1l, kIcr1h, kTcnt2}) take_read(a);
}

void AvrChip::io_write_atmega16(std::uint16_t addr, std::uint8_t v) {
    const Cycle c = now();
    std::uint8_t* data = m_avr->data;
    TimerUnit& t0 = *m_timers[0];
    TimerUnit& t1 = *m_timers[1];
    TimerUnit& t2 = *m_timers[2];
    const auto write_tccr = [&](TimerUnit& t) {
        t.write_tccra(c, tccra_of(v));
        t.write_tccrb(c, tccrb_of(v));
        data[addr] = static_cast<std::uint8_t>(v & 0x7FU);  // FOCn reads as zero
    };
    switch (addr) {
        case kMcucr:
            data[addr] = v;
            break;  // ISC bits read at each edge; SE/SM by simavr's sleep
        case kGicr:
            write_gicr(v);
            break;
        case kGifr:
            write_gifr(v);
            break;
        case kTifr:
            write_timer_flags(addr, v);
            break;
        case kTimsk:
            write_timsk(addr, v);
            break;
        case kSfior: {
            for (auto& t : m_timers) t->advance_to(c);
            if ((v & kPsr10) != 0) m_prescaler01.restart(c);
            if ((v & kPsr2) != 0) m_prescaler2.restart(c);
            data[addr] = static_cast<std::uint8_t>(v & ~(kPsr10 | kPsr2));
            break;
        }
        case kTccr0:
            write_tccr(t0);
            break;
        case kOcr0:
            t0.write_ocr(c, Channel::A, v);
            data[addr] = v;
            break;
        case kTccr1a:
            t1.write_tccra(c, static_cast<std::uint8_t>(v & 0xF3U));
            t1.write_tccrc(c, static_cast<std::uint8_t>((v & 0x0CU) << 4));  // FOC1A/B to the 328P's TCCR1C 7:6
            data[addr] = static_cast<std::uint8_t>(v & 0xF3U);
            break;
        case kTccr1b:
            t1.write_tccrb(c, v);
            data[addr] = t1.tccrb();
            break;
        case kTccr2:
            write_tccr(t2);
            break;
        case kOcr2:
            t2.write_ocr(c, Channel::A, v);
            data[addr] = v;
            break;
        default:
            if (!write_shared_timer_reg(addr, v) && !write_usart_reg(addr, v) && port_reg_index(addr))
                port_write(addr, v);
            break;
    }
}

namespace {

int int_number(const Pin& pin) {
    return pin.port == 'D' && (pin.bit == 2 || pin.bit == 3) ? pin.bit - 2 : -1;
}

}  // namespace

void AvrChip::external_interrupt_edge(const Pin& pin, bool was, bool now_level) {
    const int n = int_number(pin);
    if (n < 0) return;
    const unsigned mode = (m_avr->data[kMcucr] >> (2 * n)) & 3U;
    const bool fires = mode == 0   ? !now_level
                       : mode == 1 ? was != now_level
                       : mode == 2 ? was && !now_level
                                   : !was && now_level;
    if (fires) raise(n == 0 ? kVecInt0 : kVecInt1, now());
}

void AvrChip::external_interrupt_entered(int vector_number) {
    if (vector_number != kVecInt0 && vector_number != kVecInt1) return;
    const int n = vector_number - kVecInt0;
    const bool low_level_mode = ((m_avr->data[kMcucr] >> (2 * n)) & 3U) == 0;
    if (low_level_mode && !pin_level(Pin{'D', 2 + n})) raise(vector_number, now());
}

void AvrChip::write_gicr(std::uint8_t v) {
    m_avr->data[kGicr] = v;
    // An enable written while the flag is set fires at once (simavr queues only at the raise).
    for (const int n : {kVecInt0, kVecInt1}) {
        avr_int_vector_t* vec = m_vectors[static_cast<std::size_t>(n)];
        if (avr_regbit_get(m_avr, vec->enable) != 0 && avr_regbit_get(m_avr, vec->raised) != 0 && vec->pending == 0)
            avr_raise_interrupt(m_avr, vec);
    }
}

void AvrChip::write_gifr(std::uint8_t v) {
    bool set = false;
    if (const auto bit = single_bit_instruction(kGifr, &set)) v = set ? static_cast<std::uint8_t>(1U << *bit) : 0;
    for (const int n : {kVecInt0, kVecInt1}) {
        avr_int_vector_t* vec = m_vectors[static_cast<std::size_t>(n)];
        const std::uint8_t bit = n == kVecInt0 ? kIntf0 : kIntf1;
        if ((v & bit) != 0 && avr_regbit_get(m_avr, vec->raised) != 0) avr_clear_interrupt(m_avr, vec);
    }
}

}  // namespace cnc::avr
