// The event-driven SystemC top against the cycle-ticked reference: the same rx waveform must give identical
// edge times on every output pin (and on the exported internal pulses).
#include <gtest/gtest.h>

#include "fpga_test_support.hpp"
#include "reference_fpga.hpp"

namespace cnc::fpga::test {
namespace {

// Builds the bench, runs model and reference to `last_edge` and checks the pin edges are identical.
void compare(FpgaBench& bench, const FpgaConfig& cfg, const UartWave& wave, std::int64_t last_edge) {
    bench.run_to_edge(last_edge);
    const auto reference = ref::run_reference(cfg, wave.changes(), last_edge);
    expect_same_edges(reference, bench.logs());
    // The scenario must have moved something, or the comparison proves nothing.
    EXPECT_GT(reference.at("step_x").edges.size(), 10U);
}

void expect_mixed_stream_records(const Top& top) {
    const FpgaStats s = top.stats();
    EXPECT_EQ(s.framing_errors, 1U);
    EXPECT_EQ(s.watchdog_resets, 2U);
    EXPECT_EQ(s.acks_dropped, 1U);
    EXPECT_EQ(s.acks_sent, 13U);
    EXPECT_EQ(s.bytes_received, 2U * 9 + 15U * 11 + 10 + 5);
    const auto packets = top.packets();
    ASSERT_EQ(packets.size(), 15U);
    for (std::size_t i = 0; i < packets.size(); ++i) EXPECT_EQ(packets[i].accepted, i != 8) << i;
    EXPECT_EQ(packets[0].period_x_cycles, 300U);
    EXPECT_EQ(packets[0].period_y_cycles, 600U);
    EXPECT_EQ(packets[9].period_x_cycles, 300U);  // the init sent during a move was not latched
    EXPECT_EQ(packets[11].t_ack_start_ps, -1);    // dropped
    EXPECT_GT(packets[10].t_ack_start_ps, 0);
    EXPECT_GE(packets[11].t_pkt_valid_ps, packets[10].t_busy_fall_ps);  // accepted right after the busy fall
    ASSERT_EQ(top.inits().size(), 2U);
    EXPECT_TRUE(top.inits()[0].applied);
    EXPECT_FALSE(top.inits()[1].applied);
    EXPECT_EQ(top.inits()[1].num_x, 150'000U);
}

TEST(FpgaVsReference, MixedStreamFromA50MHzSender) {
    const FpgaConfig cfg;
    UartWave w = sync_sender();
    const std::int64_t last = mixed_stream(w);
    FpgaBench bench("bench", cfg, w.changes());
    compare(bench, cfg, w, last);
    expect_mixed_stream_records(bench.top);
}

TEST(FpgaVsReference, MixedStreamFromTheCp2102) {
    const FpgaConfig cfg;
    UartWave w = cp2102_sender();
    const std::int64_t last = mixed_stream(w);
    FpgaBench bench("bench", cfg, w.changes());
    compare(bench, cfg, w, last);
    expect_mixed_stream_records(bench.top);
}

// The 100 ms watchdog at its boundary clock (seed 000 appendix, packet_decoder: timeout_cnt counts the clocks since
// the last byte and clears a partial packet when it reaches TIMEOUT_CYCLES): a packet's last byte whose start bit
// comes exactly watchdog_cycles clocks after the previous byte's reaches the decoder on the clock the count would
// clear it, and completes the packet; one clock later the partial packet is gone and the byte alone starts a new
// one. The sender is clocked like the FPGA, so a start bit moved by n clocks moves rx_valid by n clocks.
TEST(FpgaVsReference, TheWatchdogClearsAPartialPacketOneClockAfterItsBoundary) {
    const FpgaConfig cfg;
    const std::vector<std::uint8_t> p = motion_packet(1, 20, -10, 1000);
    std::vector<UartWave> waves;
    std::int64_t last = 0;
    for (const std::int64_t late_cycles : {0, 1}) {
        UartWave w = sync_sender();
        w.bytes(10 * kUs, init_packet(300'000, 200'000));
        w.bytes(2 * kMs, {p.begin(), p.end() - 1});
        const TimePs last_byte_ps = w.frame_starts().back() + (cfg.watchdog_cycles + late_cycles) * kCyclePs;
        w.byte(last_byte_ps, p.back());
        last = std::max(last, edge_of(last_byte_ps + 20 * kMs));
        waves.push_back(std::move(w));
    }
    FpgaBench on_time("on_time", cfg, waves[0].changes());
    FpgaBench late("late", cfg, waves[1].changes());
    on_time.run_to_edge(last);
    late.run_to_edge(last);
    const auto reference_on_time = ref::run_reference(cfg, waves[0].changes(), last);
    const auto reference_late = ref::run_reference(cfg, waves[1].changes(), last);
    expect_same_edges(reference_on_time, on_time.logs());
    expect_same_edges(reference_late, late.logs());
    EXPECT_EQ(reference_on_time.at("step_x").edges.size(), 2U * 20);  // 20 X steps: rise and fall
    EXPECT_EQ(reference_late.at("step_x").edges.size(), 0U);
    EXPECT_EQ(on_time.top.packet_count(), 1U);
    EXPECT_EQ(on_time.top.stats().watchdog_resets, 0U);
    EXPECT_EQ(late.top.packet_count(), 0U);
    EXPECT_EQ(late.top.stats().watchdog_resets, 1U);
}

// A run that drops its packet records as it reads them (fpga-uart) must see the later ones as a run that keeps
// them all: the mixed stream twice, side by side, one dropping at 25 ms what it has seen (packets 0-9, the lost
// packet 8 among them), before packet 10 (its ACK sent) and 11 (accepted during that ACK, its own ACK dropped).
TEST(FpgaVsReference, PacketRecordsDroppedMidRunLeaveTheLaterOnesAsTheyWere) {
    const FpgaConfig cfg;
    UartWave w = cp2102_sender();
    const std::int64_t last = mixed_stream(w);
    FpgaBench whole("whole", cfg, w.changes());
    FpgaBench dropping("dropping", cfg, w.changes());
    dropping.run_to_edge(edge_of(25 * kMs));
    const std::size_t seen = dropping.top.packet_count();
    ASSERT_EQ(seen, 10U);
    dropping.top.drop_packets_before(seen);
    dropping.run_to_edge(last);
    expect_mixed_stream_records(whole.top);
    const auto all = whole.top.packets();
    const auto kept = dropping.top.packets();
    EXPECT_EQ(dropping.top.packet_count(), all.size());
    ASSERT_EQ(kept.size(), all.size() - seen);
    for (std::size_t j = 0; j < kept.size(); ++j) {
        const PacketRecord& a = all[seen + j];
        const PacketRecord& b = kept[j];
        EXPECT_EQ(b.t_pkt_valid_ps, a.t_pkt_valid_ps) << j;
        EXPECT_EQ(b.steps_x, a.steps_x) << j;
        EXPECT_EQ(b.steps_y, a.steps_y) << j;
        EXPECT_EQ(b.accepted, a.accepted) << j;
        EXPECT_EQ(b.period_x_cycles, a.period_x_cycles) << j;
        EXPECT_EQ(b.t_busy_fall_ps, a.t_busy_fall_ps) << j;
        EXPECT_EQ(b.t_ack_start_ps, a.t_ack_start_ps) << j;
    }
}

TEST(FpgaVsReference, ShortAndZeroPeriods) {
    const FpgaConfig cfg;
    UartWave w = cp2102_sender();
    w.bytes(10 * kUs, init_packet(1'000, 1'000));
    w.bytes(2 * kMs, motion_packet(1, 5, 0, 2000));   // num/feed = 0: never steps, RUN 1 cycle
    w.bytes(4 * kMs, motion_packet(1, 4, 3, 20));     // 50 / 66 cycles: one long pulse per axis
    w.bytes(6 * kMs, motion_packet(1, 1, 0, 1000));   // period 1, one step: STEP never rises
    w.bytes(8 * kMs, motion_packet(1, 3, -2, 1000));  // period 1 on both axes
    w.bytes(10 * kMs, motion_packet(1, 40, 30, 5));   // 200 / 266 cycles
    FpgaBench bench("bench", cfg, w.changes());
    compare(bench, cfg, w, edge_of(12 * kMs));
    const auto packets = bench.top.packets();
    ASSERT_EQ(packets.size(), 5U);
    EXPECT_EQ(packets[0].period_x_cycles, 0U);
    EXPECT_EQ(packets[0].t_busy_fall_ps - packets[0].t_pkt_valid_ps, 204 * kCyclePs);
    EXPECT_EQ(packets[1].period_y_cycles, 66U);
}

TEST(FpgaVsReference, PacketOnTheBusyFallEdgeIsAcceptedOneEdgeEarlierIsLost) {
    // 50 MHz sender, back-to-back packets: pkt_valid comes 11 frames = 47,740 edges after the previous one, and
    // busy falls 203 + N edges after it. N = 47,537 puts the second pkt_valid on the busy-fall edge, N = 47,538
    // one edge before it.
    const FpgaConfig cfg;
    UartWave w = sync_sender();
    w.bytes(10 * kUs, init_packet(6'791'000, 47'538'000));
    TimePs t = w.bytes(2 * kMs, motion_packet(1, 7, 0, 1000));  // 7 x 6,791 = 47,537
    w.bytes(t, motion_packet(0, 0, 0, 100));
    t = w.bytes(6 * kMs, motion_packet(1, 0, 1, 1000));  // 1 x 47,538
    w.bytes(t, motion_packet(0, 0, 0, 100));
    FpgaBench bench("bench", cfg, w.changes());
    compare(bench, cfg, w, edge_of(9 * kMs));
    const auto packets = bench.top.packets();
    ASSERT_EQ(packets.size(), 4U);
    EXPECT_EQ(packets[1].t_pkt_valid_ps, packets[0].t_busy_fall_ps);
    EXPECT_TRUE(packets[1].accepted);
    EXPECT_EQ(packets[1].t_ack_start_ps, -1);  // its busy falls 203 edges later, during the first ACK
    EXPECT_EQ(packets[3].t_pkt_valid_ps, packets[2].t_busy_fall_ps - kCyclePs);
    EXPECT_FALSE(packets[3].accepted);
    EXPECT_EQ(bench.top.stats().acks_dropped, 1U);
}

TEST(FpgaVsReference, GlitchJustBeforeAStartBitMovesTheSamplingPoints) {
    // A 5 ns glitch across an edge puts uart_rx in S_START; the real start bit comes 100 cycles later and is
    // still low at the HALF_BIT check, so the byte is sampled from the glitch (117 cycles into each bit) and
    // pkt_valid comes 100 edges early.
    const FpgaConfig cfg;
    UartWave w = sync_sender();
    const std::vector<std::uint8_t> p = motion_packet(1, 9, 4, 3000);
    w.bytes(2 * kMs, {p.begin(), p.end() - 1});
    const TimePs last_start = 3 * kMs;
    // Sampled by edge 149,901; the start bit by edge 150,001.
    const TimePs glitch = last_start - 99 * kCyclePs - 2 * kPsPerNs;
    w.glitch(glitch, 5 * kPsPerNs);
    w.byte(last_start, p.back());
    FpgaBench bench("bench", cfg, w.changes());
    compare(bench, cfg, w, edge_of(4 * kMs));
    const auto packets = bench.top.packets();
    ASSERT_EQ(packets.size(), 1U);
    EXPECT_EQ(packets[0].feed, 3000);
    EXPECT_EQ(packets[0].t_pkt_valid_ps / kCyclePs, first_edge_after(glitch, kCyclePs) + 2 + 4'124);
    EXPECT_EQ(packets[0].t_pkt_valid_ps / kCyclePs, first_edge_after(last_start, kCyclePs) + 2 + 4'124 - 100);
}

TEST(FpgaVsReference, UnwiredInitPacketAndWrap32) {
    FpgaConfig cfg;
    cfg.init_packet_wired = false;
    cfg.period_arithmetic = PeriodArithmetic::Wrap32;
    UartWave w = cp2102_sender();
    w.bytes(10 * kUs, init_packet(9'375'000, 9'375'000));
    w.bytes(2 * kMs, motion_packet(1, 40, -20, 6000));  // 3,125 / 6,250 cycles with the default numerators
    w.bytes(6 * kMs, motion_packet(0, -3, 1, 60'000));
    FpgaBench bench("bench", cfg, w.changes());
    compare(bench, cfg, w, edge_of(9 * kMs));
    const auto packets = bench.top.packets();
    ASSERT_EQ(packets.size(), 2U);
    EXPECT_EQ(packets[0].period_x_cycles, 3'125U);
    EXPECT_EQ(packets[0].period_y_cycles, 6'250U);
    ASSERT_EQ(bench.top.inits().size(), 1U);
    EXPECT_FALSE(bench.top.inits()[0].applied);
}

}  // namespace
}  // namespace cnc::fpga::test
