// Seed 000 numbers through the event-driven SystemC top, driven by a bit-level UART waveform at 115200 Bd:
// the worked packet, the cycle timeline (models/fpga/README.md), §3.4.7, the 32-bit period overflow, the init
// packet wiring, and the process-activation budget (the model wakes per edge, never per clock).
#include <gtest/gtest.h>

#include <algorithm>

#include "common/crc16.hpp"
#include "fpga_test_support.hpp"

namespace cnc::fpga::test {
namespace {

const std::vector<std::uint8_t> kWorkedInit{0xFF, 0x01, 0x1E, 0x1A, 0x30, 0x01, 0x1E, 0x1A, 0x30};
const std::vector<std::uint8_t> kWorkedMotion{0x01, 0x00, 0x00, 0x01, 0x40, 0xFF, 0xFF, 0xFF, 0x60, 0x04, 0xB0};
constexpr std::int64_t kRunCycles = 320LL * 15'625;  // N = abs_dom * period_dom = 5,000,000

// rx_valid of a byte whose start bit is first seen by rx_s1 at edge e comes at e + 2 (synchroniser) + 4123;
// the decoder registers pkt_valid one edge later.
std::int64_t pkt_valid_edge_for_last_start_bit(TimePs t_start_bit) {
    return first_edge_after(t_start_bit, kCyclePs) + 2 + 4'123 + 1;
}

// Samples a UART frame on a logged line at mid-bit; returns the byte, or -1 for a low stop bit.
int decode_frame(const EdgeLog& line, TimePs t_start_bit, TimePs bit_ps) {
    int byte = 0;
    for (int i = 0; i < 8; ++i) {
        if (line.level_at(t_start_bit + bit_ps * (i + 1) + bit_ps / 2)) byte |= 1 << i;
    }
    return line.level_at(t_start_bit + bit_ps * 9 + bit_ps / 2) ? byte : -1;
}

std::vector<std::int64_t> edges_in_cycles(const std::vector<TimePs>& times) {
    std::vector<std::int64_t> out;
    for (const TimePs t : times) out.push_back(t / kCyclePs);
    return out;
}

std::vector<std::int64_t> pulse_train(std::int64_t first, std::int64_t period, std::int64_t count) {
    std::vector<std::int64_t> out;
    for (std::int64_t m = 0; m < count; ++m) out.push_back(first + m * period);
    return out;
}

// The worked example end to end; `w` decides the sender clock.
void check_worked_example(UartWave w) {
    w.bytes(20 * kUs, kWorkedInit);
    w.bytes(2 * kMs, kWorkedMotion);
    const std::int64_t k = pkt_valid_edge_for_last_start_bit(w.frame_starts().back());
    FpgaBench bench("bench", FpgaConfig{}, w.changes());
    bench.run_to_edge(k + kRunCycles + 10'000);
    const auto logs = bench.logs();

    EXPECT_EQ(edges_in_cycles(logs.at("pkt_valid").rising()), std::vector<std::int64_t>{k});
    // §5.2.4 timeline: k+1 busy, k+2 DIR and laser, k+203 first STEP, k+203+N busy falls, k+204+N tx_start.
    EXPECT_EQ(edges_in_cycles(logs.at("busy").rising()), std::vector<std::int64_t>{k + 1});
    EXPECT_EQ(edges_in_cycles(logs.at("busy").falling()), std::vector<std::int64_t>{k + 203 + kRunCycles});
    EXPECT_EQ(edges_in_cycles(logs.at("dir_x").rising()), std::vector<std::int64_t>{k + 2});
    EXPECT_TRUE(logs.at("dir_y").edges.empty());  // StepsY < 0: DIR_Y = 0, its reset level
    EXPECT_EQ(edges_in_cycles(logs.at("step_x").rising()), pulse_train(k + 203, 15'625, 320));  // 312.5 us
    EXPECT_EQ(edges_in_cycles(logs.at("step_x").falling()), pulse_train(k + 303, 15'625, 320));
    EXPECT_EQ(edges_in_cycles(logs.at("step_y").rising()), pulse_train(k + 203, 31'250, 160));  // 625 us
    EXPECT_EQ(edges_in_cycles(logs.at("step_y").falling()), pulse_train(k + 303, 31'250, 160));
    EXPECT_EQ(logs.at("step_x").falling()[0] - logs.at("step_x").rising()[0], 2 * kPsPerUs);  // STEP high 2.000 us
    const TimePs dir_setup_ps = logs.at("step_x").rising()[0] - logs.at("dir_x").rising()[0];
    EXPECT_EQ(dir_setup_ps, 201 * kCyclePs);  // 4.02 us >= DIR_SETTLE 4 us
    // laser <= engrave & busy: one clock behind busy on both edges.
    EXPECT_EQ(edges_in_cycles(logs.at("laser").rising()), std::vector<std::int64_t>{k + 2});
    EXPECT_EQ(edges_in_cycles(logs.at("laser").falling()), std::vector<std::int64_t>{k + 204 + kRunCycles});
    // ACK: tx_start one edge after the busy fall, start bit two edges later, 0xAA at 434 cycles per bit.
    const std::int64_t busy_fall = k + 203 + kRunCycles;
    EXPECT_EQ(edges_in_cycles(logs.at("tx_start").rising()), std::vector<std::int64_t>{busy_fall + 1});
    const std::vector<TimePs> tx_falls = logs.at("tx").falling();
    ASSERT_FALSE(tx_falls.empty());
    EXPECT_EQ(tx_falls[0] / kCyclePs, busy_fall + 3);
    EXPECT_EQ(decode_frame(logs.at("tx"), tx_falls[0], 434 * kCyclePs), 0xAA);
    EXPECT_EQ(logs.at("tx").edges.back().t_ps / kCyclePs, busy_fall + 3 + 8 * 434);  // last edge: bit 7 = 1

    const auto packets = bench.top.packets();
    ASSERT_EQ(packets.size(), 1U);
    const PacketRecord& p = packets[0];
    EXPECT_EQ(p.t_pkt_valid_ps, k * kCyclePs);
    EXPECT_EQ(p.motion, 1);
    EXPECT_EQ(p.steps_x, 320);
    EXPECT_EQ(p.steps_y, -160);
    EXPECT_EQ(p.feed, 1200);
    EXPECT_TRUE(p.accepted);
    EXPECT_EQ(p.period_x_cycles, 15'625U);
    EXPECT_EQ(p.period_y_cycles, 31'250U);
    EXPECT_FALSE(p.period_overflow);
    EXPECT_EQ(p.t_run_start_ps, (k + 203) * kCyclePs);
    EXPECT_EQ(p.t_busy_fall_ps, busy_fall * kCyclePs);
    EXPECT_EQ(p.t_ack_start_ps, (busy_fall + 1) * kCyclePs);
    ASSERT_EQ(bench.top.inits().size(), 1U);
    EXPECT_EQ(bench.top.inits()[0].num_x, 18'750'000U);
    EXPECT_TRUE(bench.top.inits()[0].applied);
    const FpgaStats s = bench.top.stats();
    EXPECT_EQ(s.bytes_received, 20U);
    EXPECT_EQ(s.acks_sent, 1U);
    EXPECT_EQ(bench.top.pkt_count(), 1);
}

// The packet check (protocol.crc = "crc16"): the worked packet with its CRC-16/CCITT-FALSE (computed here), first
// with one bit inverted: NAK 0x55 at once, as an ACK leaves uart_tx (tx_start the edge after the decoder's strobe, the
// start bit two edges later), and no move; then as sent: the move and its ACK 0xAA at busy's fall as in the seed; then
// again with the same sequence bit (its ACK lost on the way): ACKed at once, not run twice.
TEST(FpgaGolden, CheckedPacketsAreNakedRunAndAckedOnce) {
    std::vector<std::uint8_t> good = kWorkedMotion;
    const std::uint16_t crc = crc16(good.data(), good.size());
    good.push_back(static_cast<std::uint8_t>(crc >> 8U));
    good.push_back(static_cast<std::uint8_t>(crc & 0xFFU));
    std::vector<std::uint8_t> bad = good;
    bad[3] ^= 0x04;
    UartWave w = sync_sender();
    w.bytes(20 * kUs, bad);
    const std::int64_t k_bad = pkt_valid_edge_for_last_start_bit(w.frame_starts().back());
    w.bytes(3 * kMs, good);
    const std::int64_t k = pkt_valid_edge_for_last_start_bit(w.frame_starts().back());
    const std::int64_t busy_fall = k + 203 + kRunCycles;
    w.bytes((busy_fall + 50'000) * kCyclePs, good);
    const std::int64_t k_again = pkt_valid_edge_for_last_start_bit(w.frame_starts().back());
    FpgaConfig cfg;
    cfg.packet_crc = true;
    FpgaBench bench("bench", cfg, w.changes());
    bench.run_to_edge(k_again + 10'000);
    const auto logs = bench.logs();

    EXPECT_EQ(edges_in_cycles(logs.at("pkt_valid").rising()), std::vector<std::int64_t>{k});
    EXPECT_EQ(edges_in_cycles(logs.at("busy").rising()), std::vector<std::int64_t>{k + 1});
    EXPECT_EQ(edges_in_cycles(logs.at("tx_start").rising()),
              (std::vector<std::int64_t>{k_bad + 1, busy_fall + 1, k_again + 1}));
    const std::vector<TimePs> tx_falls = logs.at("tx").falling();
    ASSERT_GE(tx_falls.size(), 3U);
    EXPECT_EQ(tx_falls[0] / kCyclePs, k_bad + 3);
    EXPECT_EQ(decode_frame(logs.at("tx"), tx_falls[0], 434 * kCyclePs), 0x55);
    const std::vector<TimePs> starts = {tx_falls[0], (busy_fall + 3) * kCyclePs, (k_again + 3) * kCyclePs};
    EXPECT_EQ(decode_frame(logs.at("tx"), starts[1], 434 * kCyclePs), 0xAA);
    EXPECT_EQ(decode_frame(logs.at("tx"), starts[2], 434 * kCyclePs), 0xAA);
    EXPECT_EQ(edges_in_cycles(logs.at("step_x").rising()), pulse_train(k + 203, 15'625, 320));  // one run only
    const FpgaStats st = bench.top.stats();
    EXPECT_EQ(st.crc_errors, 1U);
    EXPECT_EQ(st.naks_sent, 1U);
    EXPECT_EQ(st.repeats, 1U);
    EXPECT_EQ(st.acks_sent, 1U);  // at busy's fall; the repeat's ACK is counted as a repeat
}

// The packet queue (fpga.queue_depth = 4, with the packet check): the worked packet numbered 0 and again numbered 1
// (bits 6:2 of its first byte), back to back on the wire. Packet 0 is taken the edge after the decoder completes it
// and goes to step_gen there; packet 1 arrives while move 0 runs, waits in the queue and goes to step_gen at the edge
// move 0's busy falls, so that step_gen, IDLE at the next edge, starts it at once: its first STEP 203 clocks after
// busy's fall, one period plus 203 clocks after move 0's last. Each answer is the 2-byte status of
// common/queue_protocol.hpp, its bytes written out here from the frame: 11 running free, 10 refused next. Then packet 1
// sent again is answered (not run again), and packet 3 (2 is next) is refused.
TEST(FpgaGolden, QueuedPacketsRunBackToBackAndEachIsAnsweredWithTheStatus) {
    const auto numbered = [](std::uint8_t seq) {
        std::vector<std::uint8_t> p = kWorkedMotion;
        p[0] = static_cast<std::uint8_t>(p[0] | (seq << 2U));
        const std::uint16_t crc = crc16(p.data(), p.size());
        p.push_back(static_cast<std::uint8_t>(crc >> 8U));
        p.push_back(static_cast<std::uint8_t>(crc & 0xFFU));
        return p;
    };
    UartWave w = sync_sender();
    const TimePs p0_end = w.bytes(20 * kUs, numbered(0));
    const std::int64_t k0 = pkt_valid_edge_for_last_start_bit(w.frame_starts().back());
    w.bytes(p0_end, numbered(1));
    const std::int64_t fall0 = k0 + 1 + 203 + kRunCycles;
    const std::int64_t fall1 = fall0 + 203 + kRunCycles;
    w.bytes((fall1 + 50'000) * kCyclePs, numbered(1));
    w.bytes((fall1 + 200'000) * kCyclePs, numbered(3));
    const std::int64_t k_last = pkt_valid_edge_for_last_start_bit(w.frame_starts().back());
    FpgaConfig cfg;
    cfg.packet_crc = true;
    cfg.queue_depth = 4;
    FpgaBench bench("bench", cfg, w.changes());
    bench.run_to_edge(k_last + 20'000);
    const auto logs = bench.logs();

    EXPECT_EQ(edges_in_cycles(logs.at("pkt_valid").rising()), (std::vector<std::int64_t>{k0 + 1, fall0}));
    EXPECT_EQ(edges_in_cycles(logs.at("busy").falling()), (std::vector<std::int64_t>{fall0, fall1}));
    std::vector<std::int64_t> steps = pulse_train(k0 + 1 + 203, 15'625, 320);
    const std::vector<std::int64_t> second = pulse_train(fall0 + 203, 15'625, 320);
    steps.insert(steps.end(), second.begin(), second.end());
    EXPECT_EQ(edges_in_cycles(logs.at("step_x").rising()), steps);
    EXPECT_EQ(second.front() - (fall0 - 15'625), 15'625 + 203);

    std::vector<int> bytes;
    const EdgeLog& tx = logs.at("tx");
    for (TimePs t_start = 0;;) {
        const std::vector<TimePs> falls = tx.falling();
        const auto next = std::find_if(falls.begin(), falls.end(), [&](TimePs t) { return t >= t_start; });
        if (next == falls.end()) break;
        bytes.push_back(decode_frame(tx, *next, 434 * kCyclePs));
        t_start = *next + 10 * 434 * kCyclePs;
    }
    EXPECT_EQ(bytes, (std::vector<int>{0xE4, 0x81,    // packet 0 queued and running: 4 free, 1 next
                                       0xE3, 0x82,    // packet 1 queued behind it: 3 free, 2 next
                                       0xE4, 0x82,    // move 0 ended, move 1 running: 4 free
                                       0xC4, 0x82,    // move 1 ended: nothing running
                                       0xC4, 0x82,    // packet 1 again: answered, not queued
                                       0xC4, 0xA2}));  // packet 3: refused, 2 next
    const FpgaStats st = bench.top.stats();
    EXPECT_EQ(st.queued, 2U);
    EXPECT_EQ(st.answered_again, 1U);
    EXPECT_EQ(st.refused, 1U);
    EXPECT_EQ(st.statuses_sent, 6U);
    EXPECT_EQ(st.acks_sent, 0U);
}

// The e-stop input (fpga.estop): pressed 3 ps after edge n in the middle of the worked move, sampled by the
// synchroniser's first stage at n+1 and seen at n+2, where step_gen halts: busy falls there and the STEP lines stay
// low from then on, laser_ctrl drops the laser one clock later (n+3: within three clock periods of the press), and
// uart_tx sends the halt byte 0x4B from the next edge, as the ACK would go. No ACK, and a packet sent after the
// press does not run.
TEST(FpgaGolden, TheEstopHaltsStepGenAndTheLaserWithinThreeClocks) {
    UartWave w = sync_sender();
    w.bytes(20 * kUs, kWorkedMotion);
    const std::int64_t k = pkt_valid_edge_for_last_start_bit(w.frame_starts().back());
    const std::int64_t n = k + 203 + 100 * 15'625 + 7'777;
    const TimePs t_press = n * kCyclePs + 3;
    w.bytes((n + 100'000) * kCyclePs, kWorkedMotion);
    FpgaConfig cfg;
    cfg.estop_input = true;
    FpgaBench bench("bench", cfg, w.changes(), {{t_press, true}});
    bench.run_to_edge(n + 400'000);
    const auto logs = bench.logs();

    const std::int64_t halt = n + 2;
    EXPECT_EQ(edges_in_cycles(logs.at("busy").falling()), std::vector<std::int64_t>{halt});
    ASSERT_EQ(logs.at("laser").falling().size(), 1U);
    EXPECT_EQ(logs.at("laser").falling()[0], (halt + 1) * kCyclePs);
    EXPECT_LE(logs.at("laser").falling()[0] - t_press, 3 * kCyclePs);
    EXPECT_EQ(edges_in_cycles(logs.at("step_x").rising()), pulse_train(k + 203, 15'625, 101));
    EXPECT_EQ(edges_in_cycles(logs.at("step_y").rising()), pulse_train(k + 203, 31'250, 51));
    for (const char* pin : {"step_x", "step_y"}) {
        EXPECT_LT(logs.at(pin).edges.back().t_ps, halt * kCyclePs) << pin;
        EXPECT_FALSE(logs.at(pin).edges.back().level) << pin;
    }
    EXPECT_EQ(edges_in_cycles(logs.at("tx_start").rising()), std::vector<std::int64_t>{halt + 1});
    const std::vector<TimePs> tx_falls = logs.at("tx").falling();
    ASSERT_FALSE(tx_falls.empty());
    EXPECT_EQ(tx_falls[0] / kCyclePs, halt + 3);
    EXPECT_EQ(decode_frame(logs.at("tx"), tx_falls[0], 434 * kCyclePs), 0x4B);
    const FpgaStats st = bench.top.stats();
    EXPECT_EQ(st.halted_at_ps, halt * kCyclePs);
    EXPECT_EQ(st.acks_sent, 0U);
    const auto packets = bench.top.packets();
    ASSERT_EQ(packets.size(), 2U);
    EXPECT_EQ(packets[0].t_busy_fall_ps, halt * kCyclePs);
    EXPECT_FALSE(packets[1].accepted);
}

// The interlock (fpga.interlock): the lid opened and closed during the worked move, each change sampled at the next
// edge and seen one later, where laser_ctrl's register takes it: the laser is off from that edge + 1 (three clock
// periods after the input at most) and on again the same way; the STEPs, busy and the ACK are the seed's.
TEST(FpgaGolden, AnOpenLidHoldsTheLaserOffAndTheMoveGoesOn) {
    UartWave w = sync_sender();
    w.bytes(20 * kUs, kWorkedMotion);
    const std::int64_t k = pkt_valid_edge_for_last_start_bit(w.frame_starts().back());
    const std::int64_t open = k + 1'000'000;
    const std::int64_t close = k + 3'000'000;
    FpgaConfig cfg;
    cfg.interlock_input = true;
    FpgaBench bench("bench", cfg, w.changes(), {}, {{open * kCyclePs + 5, true}, {close * kCyclePs + 5, false}});
    bench.run_to_edge(k + kRunCycles + 10'000);
    const auto logs = bench.logs();

    EXPECT_EQ(edges_in_cycles(logs.at("laser").rising()), (std::vector<std::int64_t>{k + 2, close + 3}));
    EXPECT_EQ(edges_in_cycles(logs.at("laser").falling()),
              (std::vector<std::int64_t>{open + 3, k + 204 + kRunCycles}));
    EXPECT_EQ(edges_in_cycles(logs.at("step_x").rising()), pulse_train(k + 203, 15'625, 320));
    EXPECT_EQ(edges_in_cycles(logs.at("busy").falling()), std::vector<std::int64_t>{k + 203 + kRunCycles});
    EXPECT_EQ(bench.top.stats().acks_sent, 1U);
}

TEST(FpgaGolden, WorkedExampleFrom50MHzSender) {
    UartWave w = sync_sender();
    // Frames start on edges: the last one at 2 ms + 10 frames = cycle 143,400, so pkt_valid is at 147,527.
    EXPECT_EQ(pkt_valid_edge_for_last_start_bit(2 * kMs + 10 * 4'340 * kCyclePs), 147'527);
    check_worked_example(w);
}

TEST(FpgaGolden, WorkedExampleFromTheCp2102) {
    check_worked_example(cp2102_sender());
}

// One motion packet (after an optional init) from the 50 MHz sender, run to its end.
struct OneMoveStimulus {
    std::vector<Edge> rx_changes;
    std::int64_t k = 0;  // pkt_valid edge
};

OneMoveStimulus one_move(const std::vector<std::uint8_t>& init, const std::vector<std::uint8_t>& motion) {
    UartWave w = sync_sender();
    if (!init.empty()) w.bytes(20 * kUs, init);
    w.bytes(2 * kMs, motion);
    return {w.changes(), pkt_valid_edge_for_last_start_bit(w.frame_starts().back())};
}

struct OneMove {
    OneMoveStimulus stimulus;
    FpgaBench bench;
    std::int64_t k;
    OneMove(const FpgaConfig& cfg, const std::vector<std::uint8_t>& init, const std::vector<std::uint8_t>& motion,
            std::int64_t run_cycles)
        : stimulus(one_move(init, motion)), bench("bench", cfg, stimulus.rx_changes), k(stimulus.k) {
        bench.run_to_edge(k + 210 + run_cycles + 5'000);
    }
};

TEST(FpgaGolden, Section347RunTime) {
    constexpr std::int64_t kRun = 1600LL * 20'973;  // 33,556,800 cycles
    OneMove m(FpgaConfig{}, {}, motion_packet(1, 1600, 800, 894), kRun);
    const PacketRecord p = m.bench.top.packets().at(0);
    EXPECT_EQ(p.period_x_cycles, 20'973U);
    EXPECT_EQ(p.period_y_cycles, 41'946U);
    EXPECT_EQ((p.t_busy_fall_ps - p.t_run_start_ps) / kCyclePs, kRun);
    const auto logs = m.bench.logs();
    const auto x = edges_in_cycles(logs.at("step_x").rising());
    const auto y = edges_in_cycles(logs.at("step_y").rising());
    ASSERT_EQ(x.size(), 1600U);
    ASSERT_EQ(y.size(), 800U);
    EXPECT_EQ(x.back(), m.k + 203 + 1599LL * 20'973);
    EXPECT_EQ(y.back(), m.k + 203 + 799LL * 41'946);
}

// The 32-bit period overflow: feed 100 mm/min, 73,600 x 36,800 steps (460 mm x 230 mm at 160 steps/mm), the
// whole 276 s move.
void check_overflow_move(PeriodArithmetic arithmetic, std::uint32_t expected_period_y) {
    constexpr std::int64_t kRun = 73'600LL * 187'500;  // 13.8e9 cycles: the product that overflows
    FpgaConfig cfg;
    cfg.period_arithmetic = arithmetic;
    OneMove m(cfg, {}, motion_packet(1, 73'600, 36'800, 100), kRun);
    const PacketRecord p = m.bench.top.packets().at(0);
    EXPECT_TRUE(p.period_overflow);
    EXPECT_EQ(p.period_x_cycles, 187'500U);
    EXPECT_EQ(p.period_y_cycles, expected_period_y);
    EXPECT_EQ(p.t_busy_fall_ps / kCyclePs, m.k + 203 + kRun);
    const auto logs = m.bench.logs();
    const auto x = edges_in_cycles(logs.at("step_x").rising());
    const auto y = edges_in_cycles(logs.at("step_y").rising());
    ASSERT_EQ(x.size(), 73'600U);
    ASSERT_EQ(y.size(), 36'800U);
    EXPECT_EQ(y.back(), m.k + 203 + 36'799LL * expected_period_y);
}

TEST(FpgaGolden, OverflowMoveExact) {
    check_overflow_move(PeriodArithmetic::Exact, 375'000);
}

TEST(FpgaGolden, OverflowMoveWrap32FinishesYAfter18Seconds) {
    check_overflow_move(PeriodArithmetic::Wrap32, 24'866);  // Y done at 36,800 * 24,866 cycles = 18.3 s
}

void check_init_wiring(bool wired, std::uint32_t period_x, std::uint32_t period_y) {
    FpgaConfig cfg;
    cfg.init_packet_wired = wired;
    OneMove m(cfg, init_packet(9'375'000, 9'375'000), kWorkedMotion, 320LL * period_x);
    const PacketRecord p = m.bench.top.packets().at(0);
    EXPECT_EQ(p.period_x_cycles, period_x);
    EXPECT_EQ(p.period_y_cycles, period_y);
    const auto x = edges_in_cycles(m.bench.logs().at("step_x").rising());
    ASSERT_EQ(x.size(), 320U);
    EXPECT_EQ(x[1] - x[0], period_x);
    ASSERT_EQ(m.bench.top.inits().size(), 1U);
    EXPECT_EQ(m.bench.top.inits()[0].num_x, 9'375'000U);
    EXPECT_EQ(m.bench.top.inits()[0].applied, wired);
}

TEST(FpgaGolden, InitPacketWiredAppliesTheNumerator) {
    check_init_wiring(true, 7'812, 15'624);
}

TEST(FpgaGolden, InitPacketUnwiredLikeTheAppendixHasNoEffect) {
    check_init_wiring(false, 15'625, 31'250);
}

TEST(FpgaGolden, ProcessActivationsScaleWithEdgesNotClocks) {
    UartWave w = sync_sender();
    w.bytes(2 * kMs, kWorkedMotion);
    const std::int64_t k = pkt_valid_edge_for_last_start_bit(w.frame_starts().back());
    FpgaBench bench("bench", FpgaConfig{}, w.changes());
    bench.run_to_edge(k);
    const std::uint64_t before = bench.top.activations();
    bench.run_to_edge(k + 203 + kRunCycles + 5'000);  // the move and its ACK: 5 million clocks
    const std::uint64_t during = bench.top.activations() - before;
    const auto logs = bench.logs();
    const std::uint64_t step_edges = logs.at("step_x").edges.size() + logs.at("step_y").edges.size();
    EXPECT_EQ(step_edges, 960U);
    EXPECT_LT(during, step_edges + 50);  // 666 here: one wake-up per distinct edge time
}

}  // namespace
}  // namespace cnc::fpga::test
