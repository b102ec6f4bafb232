// The polling-loop fast-forward (models/avr/loop_skipper.hpp): it skips, and what it skips changes nothing: every
// edge at the cycle the firmware's period gives, the same edges as with every cycle executed, and no run_until
// overshooting its limit by more than an instruction and an interrupt response.
#include <gtest/gtest.h>

#include <vector>

#include "avr/avr_chip.hpp"
#include "avr/core/avr_config.hpp"

using namespace cnc::avr;

namespace {

constexpr int kHeadLine = 6;  // kPinSignals: step_x dir_x en_x step_y dir_y en_y head (PB1 by default)

struct ChipRun {
    std::vector<Cycle> head_edges;
    FastForwardStats stats;
    Cycle max_overshoot = 0;
};

// Runs `elf` to `end` in chunks of `chunk` cycles (a board's quantum, and an odd one so that the run_until
// boundaries fall everywhere in the loop).
ChipRun run_chip(const char* elf, bool fast_forward, Cycle end, Cycle chunk) {
    AvrCoreConfig cfg;
    cfg.firmware_elf = elf;
    cfg.fast_forward = fast_forward;
    AvrChip chip(cfg);
    ChipRun r;
    for (Cycle limit = chunk; limit <= end; limit += chunk) {
        chip.run_until(limit);
        r.max_overshoot = std::max(r.max_overshoot, chip.cycle() - limit);
    }
    for (const LineEvent& e : chip.take_events(end))
        if (e.line == kHeadLine) r.head_edges.push_back(e.cycle);
    r.stats = chip.fast_forward_stats();
    return r;
}

// Edge k within `slack` cycles after edge 0 + k x period: the firmware sees its event only when its current
// instruction (an interrupt) or its loop turn (a polled flag) ends.
void expect_period(const std::vector<Cycle>& edges, Cycle period, Cycle slack) {
    ASSERT_GT(edges.size(), 10U);
    for (std::size_t k = 1; k < edges.size(); ++k) {
        const Cycle late = edges[k] - edges[0] - static_cast<Cycle>(k) * period;
        EXPECT_GE(late, -slack) << "edge " << k;
        EXPECT_LE(late, slack) << "edge " << k;
    }
}

// The firmware run with and without the fast-forward: edges `period` apart within `slack`, the same both ways,
// most of the time skipped, and no run_until overshooting its limit by more than an instruction of up to 4 cycles
// ending past it and then a 4-cycle interrupt response (7).
void expect_skipped_exactly(const char* elf, Cycle chunk, Cycle period, Cycle slack) {
    constexpr Cycle kEnd = 400'000;
    const ChipRun on = run_chip(elf, true, kEnd, chunk);
    const ChipRun off = run_chip(elf, false, kEnd, chunk);
    expect_period(on.head_edges, period, slack);
    EXPECT_EQ(on.head_edges, off.head_edges);
    EXPECT_GT(on.stats.skips, static_cast<std::uint64_t>(kEnd / period / 2));
    EXPECT_GT(on.stats.skipped_cycles, static_cast<std::uint64_t>(kEnd / 2));
    EXPECT_EQ(off.stats.skipped_cycles, 0U);
    EXPECT_LE(on.max_overshoot, 7);
}

}  // namespace

TEST(FastForward, APolledTimerFlagIsMetAtEveryPeriodWithTheLoopSkipped) {
    // poll_flag.c: OCF1A every (OCR1A + 1) x 1 = 1000 cycles (datasheet CTC mode), polled by a loop of LDS (2), SBRS
    // (1) and RJMP (2): each toggle within 5 cycles of its match. A skip past a match would make its toggle late,
    // and unlike the run with every cycle executed. Runs of 977 cycles put the run_until limits everywhere.
    expect_skipped_exactly(AVR_FW_POLL_FLAG_ELF, 977, 1000, 5);
}

TEST(FastForward, ASpinLoopBetweenInterruptsIsSkippedAndTheIsrKeepsItsCycle) {
    // bench_idle.c: Timer1 CTC at clk/1 with OCR1A = 1599, its ISR toggles PB1: 1600 cycles apart, give or take the
    // cycle the interrupt waits for the spin loop's 2-cycle RJMP to end.
    expect_skipped_exactly(AVR_FW_BENCH_IDLE_ELF, 1600, 1600, 1);
}

TEST(FastForward, AProvenLoopIsSkippedAgainAfterAnInterruptThatChangesBytesItDoesNotRead) {
    // isr_and_poll.c: an interrupt every 1000 cycles counts its calls, and every 8th sets the flag the loop polls:
    // toggles 8000 cycles apart, each within a turn of the loop (some 300 cycles). After most interrupts the loop is
    // the one proven before (the count it does not read changed, the flag and the table it reads did not): from the
    // instruction the interrupt returns to, it is moved on at once to the instruction that sees the next interrupt,
    // so that little more than the interrupts runs. After every 8th its flag differs, and a skip there would make
    // that toggle late.
    constexpr Cycle kEnd = 400'000;
    expect_skipped_exactly(AVR_FW_ISR_AND_POLL_ELF, 977, 8000, 400);
    const ChipRun on = run_chip(AVR_FW_ISR_AND_POLL_ELF, true, kEnd, 977);
    EXPECT_GT(on.stats.reused, static_cast<std::uint64_t>(kEnd / 1000 / 2));
    EXPECT_GT(on.stats.skipped_cycles, static_cast<std::uint64_t>(kEnd * 85 / 100));
}

TEST(FastForward, ALoopFollowingAPinAnInterruptTogglesKeepsEveryToggleOnItsCycle) {
    // isr_pin_poll.c: the interrupt toggles PB2 through PORTB every 1001 cycles, landing on each of the loop's
    // instructions in turn; the loop reads PINB and copies PB2 onto PB1. Its bytes and registers after an interrupt
    // are those of the iteration proven before it, the pin it reads is not: the head toggles must still come 1001
    // cycles apart and as with every cycle executed.
    expect_skipped_exactly(AVR_FW_ISR_PIN_POLL_ELF, 977, 1001, 8);
}

TEST(FastForward, ABusyDelayIsSkippedTurnByTurnToEachInterrupt) {
    // delay_loop.c: a delay of 15,000 SBIW/BRNE turns at a time, an interrupt every 1233 cycles toggling the head
    // pin, landing on either instruction: each toggle on the cycle it comes with every cycle executed (a skip one
    // turn too far makes the interrupt late), and most of the delay skipped.
    constexpr Cycle kEnd = 400'000;
    const ChipRun on = run_chip(AVR_FW_DELAY_LOOP_ELF, true, kEnd, 977);
    const ChipRun off = run_chip(AVR_FW_DELAY_LOOP_ELF, false, kEnd, 977);
    ASSERT_GT(on.head_edges.size(), 300U);
    EXPECT_EQ(on.head_edges, off.head_edges);
    EXPECT_GT(on.stats.skipped_cycles, static_cast<std::uint64_t>(kEnd / 2));
    EXPECT_LE(on.max_overshoot, 7);
}
