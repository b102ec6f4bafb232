// The ATmega16 (seed 002: 8 MHz) on the AVR model: the timer modes of the seed's firmware, INT0/INT1 on falling
// edges, and the interrupt response time on both MCUs. Expected cycles from the ATmega16
// datasheet (doc2466) rules quoted in each test; the test firmwares are models/avr/firmware/tests/m16_*.c.
#include <gtest/gtest.h>

#include <vector>

#include "avr/avr_chip.hpp"
#include "avr/avr_core.hpp"
#include "avr/core/pin_map.hpp"
#include "avr_test_support.hpp"
#include "common/bad_input.hpp"

namespace {

using cnc::avr::AvrChip;
using cnc::avr::AvrCoreConfig;
using cnc::avr::Cycle;

constexpr int kStepX = 0;  // kPinSignals order
constexpr int kDirX = 1;
constexpr int kEnX = 2;
constexpr int kStepY = 3;
constexpr int kDirY = 4;
constexpr int kHead = 6;

AvrCoreConfig m16(const std::string& elf, const std::string& pins = "") {
    AvrCoreConfig cfg;
    cfg.firmware_elf = elf;
    cfg.mcu = "atmega16";
    cfg.f_cpu_hz = 8'000'000;  // seed 002 §2.5.3 F_CPU
    if (!pins.empty()) cfg.pins = cnc::avr::parse_pin_map(pins, "test");
    return cfg;
}

struct Edges {
    std::vector<Cycle> rise, fall;
};

Edges edges_of(AvrChip& chip, int line, Cycle upto) {
    chip.run_until(upto);
    Edges e;
    for (const auto& ev : chip.take_events(upto)) {
        if (ev.line == line) (ev.level ? e.rise : e.fall).push_back(ev.cycle);
    }
    return e;
}

std::vector<Cycle> all_edges(const std::vector<cnc::avr::LineEvent>& events, int line) {
    std::vector<Cycle> out;
    for (const auto& ev : events) {
        if (ev.line == line) out.push_back(ev.cycle);
    }
    return out;
}

TEST(Atmega16, InterruptResponseIsFourCyclesThenTheVectorJump) {
    // OC0 toggles at the compare match that sets OCF0 (cycle f); vector at f + 4 ("Interrupt Response Time"),
    // its RJMP (the linker's relaxation of the table's JMP) 2 cycles: the ISR's sbi at f + 6. Stock libsimavr
    // 1.6: f + 2.
    AvrChip chip(m16(AVR_FW_M16_IRQ_RESPONSE_ELF));
    chip.run_until(2000);
    const auto ev = chip.take_events(2000);
    const auto oc0 = all_edges(ev, kStepY);
    const auto isr = all_edges(ev, kDirX);
    ASSERT_FALSE(oc0.empty());
    ASSERT_EQ(isr.size(), 1U);
    EXPECT_EQ(isr.front() - oc0.front(), 4 + 2);
}

TEST(Atmega16, AvrCoreRunsItAtEightMegahertz) {
    // The same firmware through the SystemC shell: 125 000 ps per cycle, and the same 6 cycles.
    cnc::avr::test::AvrBench b(m16(AVR_FW_M16_IRQ_RESPONSE_ELF));
    b.run_until_ps(cnc::kPsPerMs);
    const auto oc0 = b.edges("step_y");
    const auto isr = b.edges("dir_x");
    ASSERT_FALSE(oc0.empty());
    ASSERT_EQ(isr.size(), 1U);
    EXPECT_EQ(isr.front() - oc0.front(), 6 * 125'000);
    EXPECT_EQ(oc0.front() % 125'000, 0);
}

TEST(Atmega16, SeedTimerModes) {
    AvrChip chip(m16(AVR_FW_M16_TIMERS_ELF, "head=PD5, en_x=PD7"));
    chip.run_until(20'000);
    const auto ev = chip.take_events(20'000);
    const auto marker = all_edges(ev, kDirX);
    ASSERT_EQ(marker.size(), 1U);
    const Cycle g = marker.front() + 1;  // both prescalers restart here
    // Timer2 CTC, N = 32, OCR2 = 3: ticks at g + 32 k (clock selected at g + 1, before the first); the tick
    // leaving 3 (the 4th) clears the counter and toggles OC2: g + 128 k.
    const auto oc2 = all_edges(ev, kEnX);
    ASSERT_GE(oc2.size(), 100U);
    for (std::size_t k = 0; k < oc2.size(); ++k) ASSERT_EQ(oc2[k], g + 128 * static_cast<Cycle>(k + 1)) << k;
    // Timer0 CTC, N = 1024, OCR0 = 2: the 3rd tick toggles OC0: g + 3072 k. T_s = (OCR0 + 1) * 128 us (§2.5.3).
    const auto oc0 = all_edges(ev, kStepY);
    ASSERT_GE(oc0.size(), 5U);
    for (std::size_t k = 0; k < oc0.size(); ++k) ASSERT_EQ(oc0[k], g + 3072 * static_cast<Cycle>(k + 1)) << k;
    EXPECT_EQ(3072 * 125'000LL, 3 * 128 * cnc::kPsPerUs);
    // Timer1 fast PWM, TOP = ICR1 = 1023, N = 1, started at w = g + 3: ticks at w + k. OC1A is set at BOTTOM
    // (the tick wrapping 1023 -> 0, tick 1024) and cleared at the tick leaving OCR1A = 300 (tick 301 of each
    // period): rises at w + 1024 j, falls 301 cycles later; 1024 cycles = 128 us = 7812.5 Hz at 8 MHz.
    const Cycle w = g + 3;
    Edges oc1a;
    for (const auto& e : ev) {
        if (e.line == kHead) (e.level ? oc1a.rise : oc1a.fall).push_back(e.cycle);
    }
    ASSERT_GE(oc1a.rise.size(), 15U);
    for (std::size_t j = 0; j < oc1a.rise.size(); ++j) {
        ASSERT_EQ(oc1a.rise[j], w + 1024 * static_cast<Cycle>(j + 1)) << j;
        if (j < oc1a.fall.size()) {
            ASSERT_EQ(oc1a.fall[j], oc1a.rise[j] + 301) << j;
        }
    }
}

TEST(Atmega16, Int0AndInt1OnFallingEdges) {
    // MCUCR ISC01/ISC11 = falling edge. A rising edge does nothing; a falling edge at cycle x sets INTFn through
    // the pin synchronizer (one cycle, "Reading the Pin": 0.5 to 1.5 cycles), the vector is entered 4 cycles
    // later and its RJMP takes 2: the ISR's sbi at x + 1 + 4 + 2. Main runs 1-cycle NOPs (no instruction to finish).
    AvrChip chip(m16(AVR_FW_M16_EXTINT_ELF));
    const cnc::avr::Pin pd2{'D', 2};
    const cnc::avr::Pin pd3{'D', 3};
    chip.run_until(1000);
    chip.drive_input(pd2, true);
    chip.drive_input(pd3, true);
    const Edges none = edges_of(chip, kDirX, 2000);
    EXPECT_TRUE(none.rise.empty());
    const Cycle x0 = chip.cycle();
    chip.drive_input(pd2, false);
    const Edges int0 = edges_of(chip, kDirX, 3000);
    ASSERT_EQ(int0.rise.size(), 1U);
    EXPECT_EQ(int0.rise.front(), x0 + 7);
    const Cycle x1 = chip.cycle();
    chip.drive_input(pd3, false);
    const Edges int1 = edges_of(chip, kDirY, 4000);
    ASSERT_EQ(int1.rise.size(), 1U);
    EXPECT_EQ(int1.rise.front(), x1 + 7);
}

TEST(Atmega16, OtherMcusAreRefused) {
    AvrCoreConfig cfg = m16(AVR_FW_M16_IRQ_RESPONSE_ELF);
    cfg.mcu = "atmega8";
    try {
        AvrChip chip(cfg);
        FAIL() << "atmega8 accepted";
    } catch (const cnc::BadInput& e) {
        EXPECT_NE(std::string(e.what()).find("MCU 'atmega8' is not modelled (modelled: atmega328p, atmega16)"),
                  std::string::npos)
            << e.what();
    }
    // A 328P firmware on the ATmega16 model: the ELF check names both.
    cfg = m16(AVR_FW_IRQ_RESPONSE_ELF);
    try {
        AvrChip chip(cfg);
        FAIL() << "328P ELF accepted";
    } catch (const cnc::BadInput& e) {
        EXPECT_NE(std::string(e.what()).find("was built for atmega328p"), std::string::npos) << e.what();
    }
}

}  // namespace
