// SystemC tests of the spi-fpga link and FPGA: the mode 0 wires, the wire and transaction paths against each
// other, STEP timing at a constant rate, rate changes in both apply modes, DIR setup/hold, counters in the
// reply, and the FIFO's full and empty behaviour. Times are asserted in FPGA clock edges (20 ns) or ps.
#include <gtest/gtest.h>

#include <algorithm>
#include <systemc>

#include "common/bad_input.hpp"
#include "spi_bench.hpp"

namespace cnc::spi::test {
namespace {

using fpga::RateApply;
using fpga::SpiFpgaConfig;
using Bytes = std::vector<std::uint8_t>;

// 16.4 us: 1 us + 72 bits at 5 MHz + 1 us.
constexpr TimePs kTransferPs = 16'400'000;

SpiConfig link(bool wires) {
    SpiConfig cfg;
    cfg.trace_wires = wires;
    return cfg;
}

SpiFpgaConfig fpga_cfg(RateApply apply) {
    SpiFpgaConfig cfg;
    cfg.rate_apply = apply;
    return cfg;
}

void run_until(TimePs t) {
    sc_core::sc_start(sc_core::sc_time::from_value(static_cast<sc_dt::uint64>(t)));
}

// Rises of a train first + k*period at edges <= last.
std::vector<std::int64_t> train_to(std::int64_t first, std::int64_t period, std::int64_t last) {
    return train(first, period, last < first ? 0 : (last - first) / period + 1);
}

std::vector<std::int64_t> concat(std::vector<std::int64_t> a, const std::vector<std::int64_t>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

// Bytes seen on `data` at the rising SCLK edges of the transfer whose SS fall is at t0 (level just before).
Bytes sample_at_rises(const EdgeLog& sclk, const EdgeLog& data, TimePs t0, TimePs t1) {
    Bytes out;
    std::size_t k = 0;
    for (const TimePs r : sclk.rising()) {
        if (r < t0 || r > t1) continue;
        if (k % 8 == 0) out.push_back(0);
        if (data.level_at(r - 1)) out.back() = static_cast<std::uint8_t>(out.back() | (0x80U >> (k % 8)));
        ++k;
    }
    return out;
}

TEST(SpiFpgaModel, ConstantRateStepsExactlyThePeriodApart) {
    // Frame at 10 us; SS rises at 26.4 us = edge 1320 -> sampled at 1321 -> pushed at 1323 -> read at 1324.
    SpiBench b("b", link(true), fpga_cfg(RateApply::AtNextPulse), {{10 * kUs, rates({5000, true}, {7919, false})}});
    const TimePs end = 60 * kMs + 10'000;  // last edge 3 000 000
    run_until(end);
    EXPECT_EQ(push_edge(10 * kUs + kTransferPs), 1323);
    // X: DIR rises at the read edge, STEP waits the 50-clock setup; Y: DIR already low, steps at once.
    EXPECT_EQ(change_edges(b.log("dir_x")), std::vector<std::int64_t>{1324});
    EXPECT_TRUE(b.log("dir_y").edges.empty());
    const auto rx = rise_edges(b.log("step_x"));
    const auto ry = rise_edges(b.log("step_y"));
    EXPECT_EQ(rx, train_to(1374, 5000, 3'000'000));
    EXPECT_EQ(ry, train_to(1324, 7919, 3'000'000));
    EXPECT_EQ(rx.size(), 600U);
    EXPECT_EQ(ry.size(), 379U);
    // Exact ps: STEP high exactly 100 clocks (2 us), rises exactly 5000 clocks (100 us) apart.
    const auto rx_ps = b.log("step_x").rising();
    const auto fx_ps = b.log("step_x").falling();
    ASSERT_EQ(fx_ps.size(), rx_ps.size());
    for (std::size_t i = 0; i < rx_ps.size(); ++i) {
        EXPECT_EQ(fx_ps[i] - rx_ps[i], 2'000'000);
        if (i > 0) {
            EXPECT_EQ(rx_ps[i] - rx_ps[i - 1], 100'000'000);
        }
    }
    EXPECT_EQ(b.fpga.count(0), 600);
    EXPECT_EQ(b.fpga.count(1), -379);
    // Event-driven: 3 M clocks, but a few wakes per pin edge (979 pulses = 1958 STEP edges) and per SCLK edge.
    EXPECT_LT(b.fpga.activations(), 3 * 1958 + 4 * 144 + 20);
}

TEST(SpiFpgaModel, Mode0WiresCarryTheCommandAndTheCounters) {
    const Bytes frame_b = rates({2500, true}, {0, true});
    SpiBench b("b", link(true), fpga_cfg(RateApply::AtNextPulse),
               {{10 * kUs, rates({5000, true}, {7919, false})}, {1 * kMs, frame_b}});
    run_until(3 * kMs);
    const EdgeLog& ss = b.log("ss");
    EXPECT_EQ(ss.falling(), (std::vector<TimePs>{10 * kUs, 1 * kMs}));
    EXPECT_EQ(ss.rising(), (std::vector<TimePs>{10 * kUs + kTransferPs, 1 * kMs + kTransferPs}));
    // SCLK of the second transfer: rising at t0 + 1 us + k x 200 ns, falling 100 ns later, 72 of each.
    const auto sclk_r = b.log("sclk").rising();
    const auto sclk_f = b.log("sclk").falling();
    ASSERT_EQ(sclk_r.size(), 144U);
    ASSERT_EQ(sclk_f.size(), 144U);
    for (std::size_t k = 0; k < 72; ++k) {
        EXPECT_EQ(sclk_r[72 + k], 1 * kMs + 1 * kUs + static_cast<TimePs>(k) * 200'000);
        EXPECT_EQ(sclk_f[72 + k], 1 * kMs + 1 * kUs + static_cast<TimePs>(k) * 200'000 + 100'000);
    }
    // MOSI sampled at the rising edges decodes the command frame.
    EXPECT_EQ(sample_at_rises(b.log("sclk"), b.log("mosi"), 1 * kMs, 1 * kMs + kTransferPs), frame_b);
    // MISO sampled at the same edges is the reply the slave loaded, and what transfer() returned.
    const Bytes miso = sample_at_rises(b.log("sclk"), b.log("miso"), 1 * kMs, 1 * kMs + kTransferPs);
    ASSERT_EQ(b.replies().size(), 2U);
    EXPECT_EQ(miso, b.replies()[1]);
    EXPECT_EQ(miso, b.fpga.frames()[1].reply);
    // Snapshot at edge s = 50001 + 2 counts rises at edges <= 50001: X 1374 + 5000k -> 10, Y 1324 + 7919k -> 7.
    EXPECT_EQ(b.fpga.frames()[1].t_snapshot_ps, 50'003 * kCyclePs);
    const Feedback fb = decode_feedback(miso, 2);
    EXPECT_EQ(fb.counts, (std::vector<std::int32_t>{10, -7}));
    EXPECT_EQ(fb.status, SlaveStatus{});
    EXPECT_EQ(between(rise_edges(b.log("step_x")), 0, 50'002).size(), 10U);
    EXPECT_EQ(between(rise_edges(b.log("step_y")), 0, 50'002).size(), 7U);
    EXPECT_EQ(b.replies()[0], (Bytes{0x80, 0, 0, 0, 0, 0, 0, 0, 0}));
    // MISO is low whenever SS is high.
    for (const Edge& e : b.log("miso").edges) {
        if (e.level) {
            EXPECT_FALSE(ss.level_at(e.t_ps)) << e.t_ps;
        }
    }
}

TEST(SpiFpgaModel, TransferTimeAtThreeMegahertzAndBackToBackTransfers) {
    // 333 333.3 ps per bit: SS is low exactly cs_setup + 72 bits / 3 MHz + cs_hold = 26 us; a second transfer
    // asked for at the same time starts ss_idle_min (1 us) after the first SS rise.
    SpiConfig cfg = link(true);
    cfg.sclk_hz = 3'000'000;
    EXPECT_NO_THROW(fpga::check_link(cfg, SpiFpgaConfig{}));
    const Bytes frame = rates({5000, true}, {7919, false});
    SpiBench b("b", cfg, fpga_cfg(RateApply::AtNextPulse), {{10 * kUs, frame}, {10 * kUs, frame}});
    run_until(1 * kMs);
    EXPECT_EQ(transfer_time_ps(cfg, 72), 26 * kUs);
    EXPECT_EQ(b.log("ss").falling(), (std::vector<TimePs>{10 * kUs, 37 * kUs}));
    EXPECT_EQ(b.log("ss").rising(), (std::vector<TimePs>{36 * kUs, 63 * kUs}));
    ASSERT_EQ(b.master.transfers().size(), 2U);
    EXPECT_EQ(b.master.transfers()[1].t_ss_fall_ps, 37 * kUs);
    EXPECT_EQ(b.master.ss_low_total_ps(), 52 * kUs);
    // Last falling SCLK edge of the first transfer: 10 us + 1 us + 71.5 bits = 34 833 333 ps (rounded down).
    EXPECT_EQ(b.log("sclk").falling()[71], 10 * kUs + 1 * kUs + 23'833'333);
    EXPECT_EQ(sample_at_rises(b.log("sclk"), b.log("mosi"), 37 * kUs, 63 * kUs), frame);
    EXPECT_EQ(sample_at_rises(b.log("sclk"), b.log("miso"), 37 * kUs, 63 * kUs), b.replies()[1]);
    EXPECT_TRUE(b.fpga.frames()[1].accepted);
}

// The oversampling slave's rule, SCLK below clk/6 (fpga::check_link): MISO changes up to 3 FPGA clocks after a
// falling SCLK edge (FPGA README: the 2-stage synchroniser, then the register that drives MISO), and the master
// reads it at the next rising edge. The SCLK edges lie at whole ps, n x 1e12 / 2f rounded down, so no half period is
// shorter than floor(1e12 / 2f). The integer rate just below 50 MHz / 6, 8 333 333 Hz, has edges exactly 60 ns
// apart: with SS on the 20 ns grid every falling edge is on a clock edge, the worst case, MISO changes exactly at the
// rising edge and the master reads the bit before. Above 60 ns (the fastest rate with every half period at least
// 60 001 ps, which check_link allows) it reads the reply.
Bytes reply_read_at(std::uint32_t sclk_hz, Bytes& loaded) {
    SpiConfig cfg = link(true);
    cfg.sclk_hz = sclk_hz;
    SpiBench b("b", cfg, fpga_cfg(RateApply::AtNextPulse), {{10 * kUs, rates({5000, true}, {7919, false})}});
    run_until(1 * kMs);
    loaded = b.fpga.frames().at(0).reply;
    return b.replies().at(0);
}

constexpr TimePs kThreeClocksPs = 3 * 20'000;  // 50 MHz
constexpr std::uint32_t kSixthHz = 50'000'000 / 6;
constexpr auto kFastestHz = static_cast<std::uint32_t>(kPsPerSec / (2 * (kThreeClocksPs + 1)));

TimePs half_period_ps(std::uint32_t sclk_hz) {
    SpiConfig cfg;
    cfg.sclk_hz = sclk_hz;
    return sclk_half_period_ps(cfg);
}

TEST(SpiFpgaModel, MisoIsReadRightAboveThreeClocksOfHalfPeriod) {
    EXPECT_EQ(half_period_ps(kFastestHz), kThreeClocksPs + 1);
    Bytes loaded;
    EXPECT_EQ(reply_read_at(kFastestHz, loaded), loaded);
}

TEST(SpiFpgaModel, MisoIsReadABitLateJustBelowASixthOfTheClock) {
    EXPECT_EQ(half_period_ps(kSixthHz), kThreeClocksPs);
    SpiConfig cfg;
    cfg.sclk_hz = kSixthHz;
    EXPECT_THROW(fpga::check_link(cfg, SpiFpgaConfig{}), cnc::BadInput);
    Bytes loaded;
    const Bytes read = reply_read_at(kSixthHz, loaded);
    ASSERT_EQ(read.size(), loaded.size());
    EXPECT_EQ(loaded[0], 0x80);  // the reply's status byte
    // Bit k is read as bit k - 1 of the reply, bit 0 (driven since SS fell) twice.
    const auto bit = [](const Bytes& v, std::size_t i) { return (v[i / 8] >> (7 - i % 8)) & 1; };
    for (std::size_t k = 1; k < 8 * loaded.size(); ++k) EXPECT_EQ(bit(read, k), bit(loaded, k - 1)) << "bit " << k;
}

TEST(SpiFpgaModel, WiresAndTransactionsGiveTheSameFpgaBehaviour) {
    const std::vector<Send> script{{10 * kUs, rates({5000, true}, {7919, false}, true)},
                                   {1 * kMs, rates({1234, false}, {7919, false})},
                                   {2 * kMs, rates({0, true}, {300, true}, true)},
                                   {2 * kMs + 500 * kUs, rates({800, true}, {0, false})}};
    SpiBench wires("wires", link(true), fpga_cfg(RateApply::Immediately), script);
    SpiBench trans("trans", link(false), fpga_cfg(RateApply::Immediately), script);
    run_until(5 * kMs);
    EXPECT_EQ(wires.log("laser").edges.size(), 4U);
    for (const char* pin : {"step_x", "dir_x", "step_y", "dir_y", "laser"}) {
        const auto& a = wires.log(pin).edges;
        const auto& c = trans.log(pin).edges;
        ASSERT_EQ(a.size(), c.size()) << pin;
        for (std::size_t i = 0; i < a.size(); ++i) {
            EXPECT_EQ(a[i].t_ps, c[i].t_ps) << pin << " #" << i;
            EXPECT_EQ(a[i].level, c[i].level) << pin << " #" << i;
        }
    }
    EXPECT_FALSE(wires.log("step_x").edges.empty());
    EXPECT_EQ(wires.replies(), trans.replies());
    ASSERT_EQ(trans.fpga.frames().size(), 4U);
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(wires.fpga.frames()[i].t_snapshot_ps, trans.fpga.frames()[i].t_snapshot_ps);
        EXPECT_EQ(wires.fpga.frames()[i].t_end_ps, trans.fpga.frames()[i].t_end_ps);
        EXPECT_TRUE(trans.fpga.frames()[i].accepted);
    }
    // The transaction path leaves the wires idle.
    EXPECT_TRUE(trans.log("ss").edges.empty());
    EXPECT_TRUE(trans.log("sclk").edges.empty());
    EXPECT_TRUE(trans.log("mosi").edges.empty());
    EXPECT_EQ(wires.log("sclk").edges.size(), 4U * 144U);
    EXPECT_LT(trans.fpga.activations(), wires.fpga.activations());
}

TEST(SpiFpgaModel, RateChangeAtNextPulseVersusImmediately) {
    // A at 10 us (read at 1324), B at 1 ms: SS rises at 1 016.4 us = edge 50820 -> read from 50824.
    const std::vector<Send> script{{10 * kUs, rates({10'000, true}, {10'000, false})},
                                   {1 * kMs, rates({3'000, true}, {20'000, false})}};
    SpiBench imm("imm", link(false), fpga_cfg(RateApply::Immediately), script);
    SpiBench next("next", link(false), fpga_cfg(RateApply::AtNextPulse), script);
    run_until(1'600'010'000);                      // last edge 80 000
    const auto before_x = train(1374, 10'000, 5);  // last rise before the change: 41374
    const auto before_y = train(1324, 10'000, 5);  // 41324
    // Immediately: X compares with 3000 at once: 41374 + 3000 is past, so it rises at the read edge 50824;
    // Y's 20000 runs from its last rise: 61324.
    EXPECT_EQ(rise_edges(imm.log("step_x")), concat(before_x, train_to(50'824, 3'000, 80'000)));
    EXPECT_EQ(rise_edges(imm.log("step_y")), concat(before_y, train_to(61'324, 20'000, 80'000)));
    // At next pulse: the running 10000-clock periods complete (51374, 51324), the new ones start there.
    EXPECT_EQ(rise_edges(next.log("step_x")), concat(before_x, train_to(51'374, 3'000, 80'000)));
    EXPECT_EQ(rise_edges(next.log("step_y")), concat(before_y, train_to(51'324, 20'000, 80'000)));
    ASSERT_EQ(imm.fpga.applied(0).size(), 2U);
    EXPECT_EQ(imm.fpga.applied(0)[1].edge, 50'824);
    EXPECT_EQ(imm.fpga.applied(0)[1].seq, 1U);
    EXPECT_EQ(next.fpga.applied(0)[1].edge, 51'374);
    EXPECT_EQ(next.fpga.applied(1)[1].edge, 51'324);
    EXPECT_EQ(next.fpga.applied(1)[1].rate, (AxisRate{20'000, false}));
}

TEST(SpiFpgaModel, LaserSwitchesAtTheEdgeTheFramesRatesAllGovern) {
    // The frames of RateChangeAtNextPulseVersusImmediately, A with the laser bit set and B without.
    const std::vector<Send> script{{10 * kUs, rates({10'000, true}, {10'000, false}, true)},
                                   {1 * kMs, rates({3'000, true}, {20'000, false}, false)}};
    SpiBench imm("imm", link(false), fpga_cfg(RateApply::Immediately), script);
    SpiBench next("next", link(false), fpga_cfg(RateApply::AtNextPulse), script);
    run_until(1'600'010'000);  // last edge 80 000
    // A finds both generators stopped: both load it at 1324 (Y's first STEP rises there), and the laser goes on.
    // Immediately: both load B at 50824 (X's first STEP at the new rate): laser off there.
    // At next pulse: Y loads B at its boundary 51324, X at 51374; the frame governs from the later: laser off.
    EXPECT_EQ(change_edges(imm.log("laser")), (std::vector<std::int64_t>{1'324, 50'824}));
    EXPECT_EQ(change_edges(next.log("laser")), (std::vector<std::int64_t>{1'324, 51'374}));
    for (const SpiBench* b : {&imm, &next}) {
        const EdgeLog& laser = b->log("laser");
        EXPECT_FALSE(laser.initial);
        ASSERT_EQ(laser.edges.size(), 2U);
        EXPECT_EQ(laser.edges[0].t_ps, 1'324 * kCyclePs);  // at the edge itself, as STEP and DIR
        EXPECT_TRUE(laser.edges[0].level);
        EXPECT_FALSE(laser.edges[1].level);
        EXPECT_EQ(rise_edges(b->log("step_y")).front(), 1'324);
        // The switch is the later of the two axes' loads of that frame.
        const auto& frames = b->fpga.applied_frames();
        ASSERT_EQ(frames.size(), 2U);
        for (std::size_t i = 0; i < 2; ++i) {
            EXPECT_EQ(frames[i].seq, i);
            EXPECT_EQ(frames[i].edge, std::max(b->fpga.applied(0)[i].edge, b->fpga.applied(1)[i].edge));
            EXPECT_EQ(frames[i].t_ps, laser.edges[i].t_ps);
            EXPECT_EQ(frames[i].laser_on, i == 0);
        }
    }
}

void expect_dir_setup_hold(const EdgeLog& dir, const EdgeLog& step, std::int64_t setup, std::int64_t hold) {
    const auto rises = rise_edges(step);
    for (const std::int64_t d : change_edges(dir)) {
        for (const std::int64_t r : rises) {
            if (r <= d) {
                EXPECT_GE(d - r, hold) << "DIR at " << d << " after STEP rise " << r;
            } else {
                EXPECT_GE(r - d, setup) << "STEP rise " << r << " after DIR at " << d;
            }
        }
    }
}

TEST(SpiFpgaModel, DirReversalRespectsSetupAndHold) {
    // B's SS rises at 107.6 us = edge 5380 -> read at 5384, 10 clocks after X's rise at 5374.
    const std::vector<Send> script{{10 * kUs, rates({1'000, true}, {0, true})},
                                   {91'200'000, rates({1'000, false}, {0, true})}};
    SpiBench imm("imm", link(true), fpga_cfg(RateApply::Immediately), script);
    SpiBench next("next", link(true), fpga_cfg(RateApply::AtNextPulse), script);
    run_until(400 * kUs + 10'000);           // last edge 20 000
    const auto fwd = train(1374, 1'000, 5);  // 1374 .. 5374
    // Immediately: DIR may not fall before 5374 + 50 (hold); the next rise is 5374 + 1000 (>= 5424 + 50).
    EXPECT_EQ(change_edges(imm.log("dir_x")), (std::vector<std::int64_t>{1324, 5424}));
    EXPECT_EQ(rise_edges(imm.log("step_x")), concat(fwd, train_to(6'374, 1'000, 20'000)));
    // At next pulse: the reversal is loaded at the boundary 6374, DIR falls there, STEP waits the setup.
    EXPECT_EQ(change_edges(next.log("dir_x")), (std::vector<std::int64_t>{1324, 6374}));
    EXPECT_EQ(rise_edges(next.log("step_x")), concat(fwd, train_to(6'424, 1'000, 20'000)));
    for (SpiBench* b : {&imm, &next}) {
        expect_dir_setup_hold(b->log("dir_x"), b->log("step_x"), 50, 50);
        EXPECT_EQ(b->fpga.count(0), 5 - 14);  // 5 forward, 14 reverse rises
        EXPECT_EQ(b->fpga.step_counter_x.forward_rises(), 5U);
        EXPECT_EQ(b->fpga.step_counter_x.reverse_rises(), 14U);
        EXPECT_TRUE(b->log("step_y").edges.empty());
    }
}

TEST(SpiFpgaModel, FifoFullDropsTheNewFrameAndEmptyKeepsTheLastRate) {
    // At next pulse with a 1e6-clock (20 ms) period: the generators read nothing for 20 ms, so frames queue.
    Bytes bad_header = rates({1'000, true}, {1'000, true});
    bad_header[0] = 0x00;
    const std::vector<Send> script{
        {10 * kUs, rates({1'000'000, true}, {1'000'000, true})},  // seq 0: read at 1324 by both axes
        {100 * kUs, rates({400'000, true}, {400'000, true})},     // seq 1..4 fill the FIFO (depth 4)
        {200 * kUs, rates({300'000, true}, {300'000, true})},
        {300 * kUs, rates({200'000, true}, {200'000, true})},
        {400 * kUs, rates({100'000, true}, {100'000, true})},
        {500 * kUs, rates({50'000, true}, {50'000, true})},  // seq 5: dropped
        {600 * kUs, rates({50'000, true}, {50'000, true})},  // seq 6: dropped
        {700 * kUs, bad_header},                             // seq 7: rejected
        {800 * kUs, rates({1'000, true}, {1'000, true})}};   // seq 8: dropped
    SpiBench b("b", link(false), fpga_cfg(RateApply::AtNextPulse), script);
    run_until(52 * kMs + 10'000);  // last edge 2 600 000
    const auto& frames = b.fpga.frames();
    ASSERT_EQ(frames.size(), 9U);
    for (std::size_t i = 0; i < 9; ++i) {
        EXPECT_EQ(frames[i].accepted, i != 7) << i;
        EXPECT_EQ(frames[i].dropped, i == 5 || i == 6 || i == 8) << i;
    }
    const auto& pushes = b.fpga.fifo_pushes();
    ASSERT_EQ(pushes.size(), 8U);
    for (std::size_t i = 1; i <= 4; ++i) EXPECT_EQ(pushes[i].level_before, i - 1) << i;
    EXPECT_EQ(pushes[5].level_before, 4U);
    // Status bytes: level, full, sticky dropped / rejected flags reported once.
    std::vector<std::uint8_t> status;
    for (const Bytes& r : b.replies()) status.push_back(r.at(0));
    EXPECT_EQ(status, (std::vector<std::uint8_t>{0x80, 0x80, 0x81, 0x82, 0x83, 0x94, 0xB4, 0xB4, 0xD4}));
    // The queue is read one frame per boundary in FIFO order; then it is empty and the last rate is kept.
    std::vector<std::int64_t> applied_edges;
    std::vector<std::uint64_t> applied_seqs;
    for (const auto& a : b.fpga.applied(0)) {
        applied_edges.push_back(a.edge);
        applied_seqs.push_back(a.seq);
    }
    EXPECT_EQ(applied_edges, (std::vector<std::int64_t>{1324, 1'001'374, 1'401'374, 1'701'374, 1'901'374}));
    EXPECT_EQ(applied_seqs, (std::vector<std::uint64_t>{0, 1, 2, 3, 4}));
    const auto expected =
        concat({1374, 1'001'374, 1'401'374, 1'701'374, 1'901'374}, train_to(2'001'374, 100'000, 2'600'000));
    EXPECT_EQ(rise_edges(b.log("step_x")), expected);
    EXPECT_EQ(rise_edges(b.log("step_y")), expected);
    EXPECT_EQ(b.fpga.count(0), 11);
}

TEST(SpiFpgaModel, ShortRateWordIsStretchedToOneLowClock) {
    // A raw word of 50 clocks (the host's encoder would refuse it): STEP keeps one low clock, 101 apart.
    const Bytes raw{kCmdRates, 0x80, 0x00, 0x00, 0x32, 0x00, 0x00, 0x00, 0x00};
    SpiBench b("b", link(false), fpga_cfg(RateApply::Immediately), {{10 * kUs, raw}});
    run_until(100 * kUs + 10'000);  // last edge 5000
    EXPECT_EQ(rise_edges(b.log("step_x")), train_to(1374, 101, 5'000));
    EXPECT_EQ(fall_edges(b.log("step_x")), train_to(1474, 101, 5'000));
    EXPECT_EQ(b.fpga.pulse_gen_x.stretched(), 1U);
    EXPECT_TRUE(b.fpga.applied(0).front().stretched);
}

}  // namespace
}  // namespace cnc::spi::test
