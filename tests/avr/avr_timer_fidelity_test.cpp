// Silicon fidelity of the ATmega328P timers (datasheet §15 Timer0, §16 Timer1, §17 prescalers, §18 Timer2),
// measured on AvrCore's SystemC pin signals while small test firmwares run (models/avr/firmware/tests).
// Every expected cycle is derived from the datasheet rules quoted in the comments; 1 cycle = 62 500 ps.
// "Stock libsimavr 1.6" numbers were measured with the same ELFs on an unmodified libsimavr (pin IRQ cycles).
#include <algorithm>

#include "avr_test_support.hpp"

using namespace cnc::avr;
using namespace cnc::avr::test;
using cnc::TimePs;

namespace {

// CTC toggle edges expected at first, first + period, ... up to `end` (the last one may fall at the run's end).
void expect_periodic(const std::vector<Cycle>& edges, Cycle first, Cycle period, Cycle end) {
    const auto expected_count = static_cast<std::size_t>((end - first) / period + 1);
    ASSERT_GE(edges.size() + 1, expected_count);
    for (std::size_t k = 0; k < edges.size(); ++k)
        ASSERT_EQ(edges[k], first + period * static_cast<Cycle>(k)) << "edge " << k;
}

}  // namespace

TEST(AvrTimerFidelity, CtcToggleOc0aEveryNTimesOcrPlusOneCycles) {
    // Timer0 CTC, OCR0A = 3, N = 1024 (seed 003 G01), COM0A = toggle. The prescaler restarts at g = marker - 1;
    // the counter ticks at g + 1024 k, reads 3 during the 4th timer clock, and the tick that leaves 3 clears it,
    // sets OCF0A and toggles OC0A: edges at g + 4096 k, N * (OCR + 1) = 4096 cycles = 256 us apart.
    AvrBench b(config_for(AVR_FW_CTC_T0_N1024_ELF));
    b.run_until_ps(5 * cnc::kPsPerMs);
    const Cycle g = first_rise(b, "dir_x") - 1;
    const auto e = edge_cycles(b, "step_x");
    EXPECT_EQ(e.size(), 19U);
    expect_periodic(e, g + 4096, 4096, 80'000);
    EXPECT_EQ(b.edges("step_x")[1] - b.edges("step_x")[0], 256'000'000);
    EXPECT_TRUE(b.log("step_x").edges.front().level);  // OC0A resets to 0: the first toggle drives it high
    // Stock libsimavr 1.6 ignores GTCCR.TSM and starts the prescaler at the TCCR0B write, 2 cycles early.
    EXPECT_NE(e.front(), g + 4096 - 2);
}

TEST(AvrTimerFidelity, CtcToggleOc2aEveryNTimesOcrPlusOneCycles) {
    // Timer2 CTC, OCR2A = 9, N = 256 (CS2 = 110), toggle OC2A = PB3 = step_y; prescaler released at g:
    // edges at g + 2560 k (N * (OCR + 1) = 2560 cycles = 160 us).
    AvrBench b(config_for(AVR_FW_CTC_T2_N256_ELF));
    b.run_until_ps(5 * cnc::kPsPerMs);
    const Cycle g = first_rise(b, "dir_x") - 1;
    const auto e = edge_cycles(b, "step_y");
    EXPECT_EQ(e.size(), 31U);
    expect_periodic(e, g + 2560, 2560, 80'000);
    EXPECT_TRUE(b.edges("step_x").empty());  // Timer0 untouched: PD6 stays low
}

TEST(AvrTimerFidelity, PrescalerRunsFreeSoTheFirstCountWaitsForItsPhase) {
    // §17.2: the prescaler free-runs from reset and is not restarted by a clock select write, so "the number of
    // system clock cycles from when the timer is enabled to the first count can be from 1 to N+1". Timer0 CTC,
    // OCR0A = 5, N = 64, clock selected at w = marker + 1: the counter ticks at the multiples of 64 after w, and
    // the 6th tick toggles OC0A; then every 6 * 64 = 384 cycles.
    AvrBench b(config_for(AVR_FW_CTC_T0_N64_FREE_ELF));
    b.run_until_ps(2 * cnc::kPsPerMs);
    const Cycle w = first_rise(b, "dir_x") + 1;
    const Cycle first_tick = (w / 64 + 1) * 64;
    const auto e = edge_cycles(b, "step_x");
    ASSERT_FALSE(e.empty());
    EXPECT_EQ(e.front(), first_tick + 5 * 64);
    expect_periodic(e, first_tick + 5 * 64, 384, 32'000);
    EXPECT_GE(first_tick - w, 1);
    EXPECT_LE(first_tick - w, 64);
    // Stock libsimavr 1.6 restarts the prescaler at the write: first edge at w + 384 (407 for this ELF).
    EXPECT_NE(e.front(), w + 384);
}

TEST(AvrTimerFidelity, CtcWithOcrZeroTogglesAtEveryTimerClock) {
    // CTC, OCR0A = 0, N = 8: the counter matches 0 during every timer clock, so every tick clears it (to 0),
    // sets OCF0A and toggles OC0A: a toggle every 8 cycles (500 ns), period 2 * N * (0 + 1) = 16 cycles.
    AvrBench b(config_for(AVR_FW_CTC_T0_OCR0_N8_ELF));
    b.run_until_ps(cnc::kPsPerMs);
    const Cycle g = first_rise(b, "dir_x") - 1;
    const auto e = edge_cycles(b, "step_x");
    EXPECT_EQ(e.size(), static_cast<std::size_t>((16'000 - (g + 8)) / 8 + 1));
    expect_periodic(e, g + 8, 8, 16'000);
    EXPECT_EQ(b.edges("step_x")[2] - b.edges("step_x")[0], 16 * kCyclePs);  // one OC0A period
}

TEST(AvrTimerFidelity, CtcWithOcrZeroAndNoPrescalerTogglesEveryCycle) {
    // CTC, OCR2A = 0, N = 1: a match at every cycle, OC2A toggles every cycle (8 MHz square wave). Stock libsimavr 1.6
    // computes prescaler * (OCR + 1) = 1, registers no timer and never toggles (so grbl's stepper never starts).
    AvrBench b(config_for(AVR_FW_CTC_T2_OCR0_N1_ELF));
    b.run_until_ps(100 * cnc::kPsPerUs);
    const Cycle w = first_rise(b, "dir_x") + 1;  // sts TCCR2B
    const auto e = edge_cycles(b, "step_y");
    ASSERT_FALSE(e.empty());
    expect_periodic(e, w + 1, 1, 1'599);
    EXPECT_EQ(e.size(), static_cast<std::size_t>(1'600 - (w + 1)));  // edges at w + 1 .. 1599 (before 100 us)
}

TEST(AvrTimerFidelity, Timer1OcrZeroCompareInterruptRuns) {
    // grbl's stepper start: Timer1 CTC (mode 4), OCR1A = 0, N = 1, OCIE1A. OCF1A is set at the first tick
    // (cycle w + 1) and the ISR runs; it sets OCR1A = 999, so from its second pass on the ISR runs every
    // (999 + 1) * 1 = 1000 cycles. The ISR toggles PB5 (dir_y). Stock libsimavr 1.6: the ISR never runs.
    AvrBench b(config_for(AVR_FW_T1_OCR0_ISR_ELF));
    b.run_until_ps(2 * cnc::kPsPerMs);
    const Cycle w = first_rise(b, "dir_x") + 1;
    const auto e = edge_cycles(b, "dir_y");
    ASSERT_GE(e.size(), 10U);
    // Interrupt response (4 cycles) plus the compiler's ISR prologue, counted from the flag at w + 1.
    EXPECT_GT(e[0], w + 1 + 4);
    EXPECT_LT(e[0], w + 1 + 40);
    // OCF1A was set again while the first pass ran (OCR1A was still 0), so the ISR runs once more right away.
    EXPECT_LT(e[1] - e[0], 60);
    for (std::size_t k = 3; k < e.size(); ++k) EXPECT_EQ(e[k] - e[k - 1], 1000) << k;
}

TEST(AvrTimerFidelity, TcntWrittenWhileStoppedIsWhereCountingStarts) {
    // Timer0 stopped, TCNT0 = 150, OCR0A = 200, N = 8, prescaler released at g: the counter counts on from 150
    // and the first compare match comes after (OCR - TCNT + 1) * N = 51 * 8 = 408 cycles, then every
    // 201 * 8 = 1608. Stock libsimavr 1.6 restarts from 0 (drops the preload): first edge after 1608 cycles.
    AvrBench b(config_for(AVR_FW_PRELOAD_T0_ELF));
    b.run_until_ps(2 * cnc::kPsPerMs);
    const Cycle g = first_rise(b, "dir_x") - 1;
    const auto e = edge_cycles(b, "step_x");
    ASSERT_FALSE(e.empty());
    EXPECT_EQ(e.front() - g, 408);
    expect_periodic(e, g + 408, 1608, 32'000);
    EXPECT_NE(e.front() - g, 1608);
}

TEST(AvrTimerFidelity, Timer2TcntWrittenWhileStoppedIsWhereCountingStarts) {
    // Timer2: TCNT2 = 90, OCR2A = 100, N = 32: first match after (100 - 90 + 1) * 32 = 352 cycles, then every
    // 101 * 32 = 3232 cycles.
    AvrBench b(config_for(AVR_FW_PRELOAD_T2_ELF));
    b.run_until_ps(2 * cnc::kPsPerMs);
    const Cycle g = first_rise(b, "dir_x") - 1;
    const auto e = edge_cycles(b, "step_y");
    ASSERT_FALSE(e.empty());
    EXPECT_EQ(e.front() - g, 352);
    expect_periodic(e, g + 352, 3232, 32'000);
}

namespace {

// Datasheet CTC rule, tick by tick (N = 1): at each tick the counter leaves its value v; if v == OCR0A the tick
// sets OCF0A, toggles OC0A and clears the counter, else the counter goes to v + 1 (0 after 0xFF). A write at
// cycle w applies to the ticks after w.
struct CtcReference {
    Cycle start;  // clock selected here: ticks at start + 1, start + 2, ...
    std::uint8_t ocr;
    std::vector<std::pair<Cycle, std::uint8_t>> ocr_writes;
    std::vector<Cycle> toggles;
    std::uint8_t tcnt_after(Cycle c) {  // runs the reference to cycle c and returns TCNT0 there
        std::uint8_t v = 0;
        toggles.clear();
        std::uint8_t o = ocr;
        std::size_t next_write = 0;
        for (Cycle t = start + 1; t <= c; ++t) {
            while (next_write < ocr_writes.size() && ocr_writes[next_write].first < t)
                o = ocr_writes[next_write++].second;
            if (v == o) {
                toggles.push_back(t);
                v = 0;
            } else {
                v = static_cast<std::uint8_t>(v + 1);
            }
        }
        return v;
    }
};

}  // namespace

TEST(AvrTimerFidelity, OcrWrittenAboveOrBelowTheRunningCount) {
    // Timer0 CTC, N = 1, OCR0A = 100 from cycle s; OCR0A = 200 written at w2 (count v2 < 200); OCR0A = 10 written
    // at w3 with the count v3 above 10. §15.7.2: the new value acts at once: after w2 the next match is when the
    // count reaches 200 (w2 + 200 - v2 + 1); after w3 the match at 10 is missed, the counter runs to 0xFF, wraps
    // (one ~256-tick period: w3 + 255 - v3 + 1 + 10 + 1) and then toggles every 11 cycles.
    AvrBench b(config_for(AVR_FW_OCR_CHANGE_ELF));
    b.run_until_ps(cnc::kPsPerMs);
    const Cycle s = first_rise(b, "dir_x") + 1;
    const Cycle w2 = first_rise(b, "dir_y") + 1;
    const Cycle w3 = first_rise(b, "en_y") + 1;
    CtcReference ref{s, 100, {{w2, 200}, {w3, 10}}, {}};
    const std::uint8_t v2 = ref.tcnt_after(w2);
    const std::uint8_t v3 = ref.tcnt_after(w3);
    ASSERT_LT(v2, 200);
    ASSERT_GT(v3, 10);
    const auto e = edge_cycles(b, "step_x");
    (void)ref.tcnt_after(16'000);
    EXPECT_EQ(e, ref.toggles);

    const auto after = [&](Cycle w) { return *std::upper_bound(e.begin(), e.end(), w); };
    EXPECT_EQ(after(w2), w2 + (200 - v2) + 1);
    EXPECT_EQ(after(w3), w3 + (255 - v3) + 1 + 10 + 1);
    const auto it = std::upper_bound(e.begin(), e.end(), w3);
    EXPECT_EQ(*(it + 1) - *it, 11);
    EXPECT_EQ(*(it + 5) - *(it + 4), 11);
}

TEST(AvrTimerFidelity, InterruptResponseIsFourCyclesThenTheVectorJump) {
    // Datasheet "Interrupt Response Time": the vector is entered at least 4 cycles after the flag (the CPU pushes
    // the return address). The vector holds an RJMP (avr-ld --relax shortens the table's JMPs; avr-objdump shows
    // `rjmp` + `nop`), 2 cycles. Timer0 CTC at N = 1 toggles OC0A at the compare match that sets OCF0A (cycle f);
    // the main program runs NOPs, so the naked ISR's first instruction (sbi PB0) starts at f + 4 + 2. Stock
    // libsimavr 1.6 charges nothing for the response: f + 2.
    AvrBench b(config_for(AVR_FW_IRQ_RESPONSE_ELF));
    b.run_until_ps(cnc::kPsPerMs);
    const auto oc0a = edge_cycles(b, "step_x");
    const auto isr = edge_cycles(b, "dir_x");
    ASSERT_FALSE(oc0a.empty());
    ASSERT_EQ(isr.size(), 1U);  // the ISR sets the pin; only its first pass makes an edge
    EXPECT_EQ(isr.front() - oc0a.front(), 4 + 2);
}

TEST(AvrTimerFidelity, WakingFromSleepAddsFourCyclesToTheResponse) {
    // Datasheet "Interrupt Response Time": "If an interrupt occurs when the MCU is in sleep mode, the interrupt
    // execution response time is increased by four clock cycles", in addition to the sleep mode's start-up time,
    // which is 0 in Idle (the clock runs on). The same ISR as above, the main program asleep: the vector at f + 8,
    // its RJMP, the sbi at f + 10. libsimavr 1.6's sleeping core lands one cycle past the flag and charged nothing
    // for the wake-up (f + 1 + 4 + 2 = f + 7 here before the wake-up was modelled).
    AvrBench b(config_for(AVR_FW_IRQ_RESPONSE_SLEEP_ELF));
    b.run_until_ps(cnc::kPsPerMs);
    const auto oc0a = edge_cycles(b, "step_x");
    const auto isr = edge_cycles(b, "dir_x");
    ASSERT_FALSE(oc0a.empty());
    ASSERT_EQ(isr.size(), 1U);
    EXPECT_EQ(isr.front() - oc0a.front(), 4 + 4 + 2);
}
