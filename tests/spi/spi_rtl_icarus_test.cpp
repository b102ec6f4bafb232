// Our Verilog of seed 004's FPGA (models/fpga/rtl/spi_*.v) under Icarus Verilog against the event-driven SystemC model
// (models/fpga/spi): the SystemC bench (spi_bench.hpp) drives the model with an SPI master over the wires; the SCLK,
// MOSI and SS changes it recorded are replayed into the RTL (rtl/spi_stream_tb.v), compiled here with the model's
// parameters, and every output pin must change at the same picosecond to the same level: STEP, DIR, laser and MISO
// (so the replies, status byte and step counters included), with nENBL held low. The frame sequence starts, reverses
// and stops axes, sends a bad command byte and a short frame (rejected), the laser bit on and off, a word below the
// shortest period (stretched), and, with rates applied at the next pulse, fills the FIFO until frames are dropped; the
// test asserts on the model that the sequence did all of that, so the comparison covers it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <systemc>
#include <vector>

#include "spi_bench.hpp"
#include "support/edge_log_diff.hpp"
#include "support/rtl_edges.hpp"
#include "support/test_path.hpp"

namespace cnc::spi::test {
namespace {

using fpga::RateApply;
using fpga::SpiFpgaConfig;
using Bytes = std::vector<std::uint8_t>;

const char* const kOutputs[] = {"miso", "step_x", "dir_x", "step_y", "dir_y", "laser"};

// The frame sequence (transfer() call times in ps; a transfer takes 16.4 us at the default link).
std::vector<Send> script() {
    Bytes bad_command = rates({1000, true}, {1000, true});
    bad_command[0] = 0x51;  // not kCmdRates: rejected
    Bytes short_frame = rates({1000, true}, {1000, true});
    short_frame.pop_back();  // 64 bits: rejected
    Bytes y_reserved = rates({2200, true}, {1700, true});
    y_reserved[5] |= 0x40;  // bit 30 of the Y word is reserved: ignored (models/spi/README.md)
    return {
        {10 * kUs, rates({2000, true}, {3000, false})},  // X forward: DIR rises, STEP after the setup; Y reverse
        // X reverses. Read at edge 21,336 (Immediately): 5 clocks after X's rise at 1331 + 10 x 2000, so the DIR
        // change waits for the hold (models/fpga/spi/README.md, cycle timeline).
        {410'240'000, rates({2500, false}, {3000, false}, true)},
        {800'013'000, rates({2500, false}, {0, true}, true)},  // Y stops; the laser stays on
        {1'100'007'100, bad_command},
        {1'300'000'000, short_frame},
        {1'500'500'000, y_reserved},  // X reverses again, Y restarts forward, laser off
        {2'000'000'000, rates({40'000, true}, {30'000, true}, true)},  // long periods: the next frames queue
        {2'040'000'000, rates({3000, true}, {3500, false})},
        {2'060'000'000, rates({2800, false}, {2600, true}, true)},
        {2'080'003'000, rates({2700, true}, {2900, false})},
        {2'100'000'000, rates({2600, false}, {2400, true}, true)},
        {2'120'000'000, rates({2500, true}, {2300, false})},  // FIFO full at depth 4: dropped
        {2'140'011'000, rates({2400, true}, {2200, false})},  // dropped too
        {2'160'000'000, rates({2300, true}, {2100, false})},  // its reply reports full and dropped
        {3'300'000'000, rates({15, true}, {2600, true})},     // 15 clocks: below pulse + 1, stretched
        {3'400'000'000, rates({0, true}, {0, true})},         // both stop
        {3'600'000'000, rates({0, true}, {0, true})},         // reads the final counters
    };
}
constexpr std::int64_t kLastEdge = 190'000;  // 3.8 ms

// Replies as the master samples them (the level just before each rising SCLK edge of a transfer).
std::vector<Bytes> replies_on(const EdgeLog& miso, const EdgeLog& sclk, const std::vector<SpiMaster::Transfer>& ts) {
    std::vector<Bytes> out;
    const auto rises = sclk.rising();
    for (const auto& t : ts) {
        Bytes bytes(t.bits / 8, 0);
        std::size_t k = 0;
        for (const TimePs r : rises) {
            if (r <= t.t_ss_fall_ps || r >= t.t_ss_rise_ps) continue;
            if (miso.level_at(r - 1)) bytes[k / 8] = static_cast<std::uint8_t>(bytes[k / 8] | (0x80U >> (k % 8)));
            ++k;
        }
        out.push_back(bytes);
    }
    return out;
}

// STEP rises signed by DIR's level at the rise (DIR never changes at a rise edge: setup and hold >= 1 clock).
std::int64_t signed_rises(const EdgeLog& step, const EdgeLog& dir) {
    std::int64_t n = 0;
    for (const TimePs r : step.rising()) n += dir.level_at(r) ? 1 : -1;
    return n;
}

std::string iverilog_params(const SpiFpgaConfig& cfg) {
    std::ostringstream s;
    const std::string p = " -Pspi_stream_tb.";
    s << p << "CLK_PS=" << fpga::clock_period_ps(cfg) << p << "FIFO_DEPTH=" << cfg.fifo_depth << p
      << "PULSE_CYCLES=" << cfg.pulse_cycles << p << "DIR_SETUP=" << cfg.dir_setup_cycles << p
      << "DIR_HOLD=" << cfg.dir_hold_cycles << p << "IMMEDIATE=" << (cfg.rate_apply == RateApply::Immediately ? 1 : 0);
    return s.str();
}

// Runs the model bench to kLastEdge, the RTL on the input the bench recorded, and compares the output pins, the
// replies and the step counts; the caller then asserts on the model what the run covered.
void expect_rtl_as_model(SpiBench& b, const SpiFpgaConfig& cfg) {
    ASSERT_EQ(fpga::clock_period_ps(cfg), kCyclePs);
    // Mid-clock, so that no edge of the model sits on the end of the run.
    sc_core::sc_start(sc_core::sc_time::from_value(static_cast<sc_dt::uint64>(kLastEdge * kCyclePs + kCyclePs / 2)));
    ASSERT_EQ(b.master.transfers().size(), script().size()) << "the script must end before the run";

    // The input waveform: every change of ss (0), sclk (1), mosi (2) in time order.
    struct Change {
        TimePs t;
        int pin;
        bool level;
    };
    std::vector<Change> changes;
    const char* const inputs[] = {"ss", "sclk", "mosi"};
    for (int pin = 0; pin < 3; ++pin) {
        for (const Edge& e : b.log(inputs[pin]).edges) changes.push_back({e.t_ps, pin, e.level});
    }
    std::stable_sort(changes.begin(), changes.end(), [](const Change& a, const Change& c) { return a.t < c.t; });
    EXPECT_TRUE(b.log("ss").initial);
    EXPECT_FALSE(b.log("sclk").initial);
    EXPECT_FALSE(b.log("mosi").initial);
    const std::string in = cnc::test::test_path("spi_in.txt");
    const std::string out = cnc::test::test_path("pins.txt");
    const std::string vvp = cnc::test::test_path("spi_stream_tb.vvp");
    {
        std::ofstream f(in);
        for (const Change& c : changes) f << c.t << ' ' << c.pin << ' ' << (c.level ? 1 : 0) << '\n';
    }
    const std::string compile = std::string(CNC_IVERILOG) + " -g2005 -Wall" + iverilog_params(cfg) + " -o " + vvp +
                                " " + CNC_SPI_TB + " " + CNC_SPI_RTL + " > " + cnc::test::test_path("iverilog.log") +
                                " 2>&1";
    ASSERT_EQ(std::system(compile.c_str()), 0) << compile;
    const std::string run = std::string(CNC_VVP) + " -n " + vvp + " +in=" + in + " +out=" + out +
                            " +edges=" + std::to_string(kLastEdge) + " > " + cnc::test::test_path("vvp.log") + " 2>&1";
    ASSERT_EQ(std::system(run.c_str()), 0) << run;
    const auto rtl = cnc::test::read_rtl_edges(out, kCyclePs);

    // Every pin is compared (no early stop), so a failure names each pin that differs and its first difference.
    for (const char* pin : kOutputs) {
        ASSERT_EQ(rtl.count(pin), 1U) << pin << " missing from " << out;
        EXPECT_EQ(cnc::test::first_difference(rtl.at(pin), b.log(pin)), "") << pin << ": RTL vs model";
    }
    // nENBL: no pin of the model (nor of the seed's FPGA); held low, drivers enabled (spi_fpga_top.v).
    for (const char* pin : {"n_enbl_x", "n_enbl_y"}) {
        ASSERT_EQ(rtl.count(pin), 1U) << pin;
        EXPECT_FALSE(rtl.at(pin).initial) << pin;
        EXPECT_TRUE(rtl.at(pin).edges.empty()) << pin;
    }

    // The replies on the RTL's MISO are the ones the model's master read, and the last one (both axes stopped before
    // it) holds each axis's step count: the model's counter, and the RTL's own STEP rises signed by its DIR.
    const auto rtl_replies = replies_on(rtl.at("miso"), b.log("sclk"), b.master.transfers());
    ASSERT_EQ(rtl_replies.size(), b.replies().size());
    for (std::size_t i = 0; i < rtl_replies.size(); ++i) EXPECT_EQ(rtl_replies[i], b.replies()[i]) << "reply #" << i;
    const Feedback last = decode_feedback(rtl_replies.back(), 2);
    EXPECT_EQ(last.counts[0], b.fpga.count(0));
    EXPECT_EQ(last.counts[1], b.fpga.count(1));
    EXPECT_EQ(signed_rises(rtl.at("step_x"), rtl.at("dir_x")), b.fpga.count(0));
    EXPECT_EQ(signed_rises(rtl.at("step_y"), rtl.at("dir_y")), b.fpga.count(1));
}

// What the sequence exercised in the model (so that the comparison above covered it).
void expect_common_coverage(const SpiBench& b) {
    const auto& frames = b.fpga.frames();
    ASSERT_EQ(frames.size(), script().size());
    EXPECT_FALSE(frames[3].accepted);  // bad command byte
    EXPECT_FALSE(frames[4].accepted);  // short frame
    EXPECT_TRUE(decode_status(b.replies()[4][0]).rejected);
    EXPECT_TRUE(decode_status(b.replies()[5][0]).rejected);
    EXPECT_GE(b.log("laser").rising().size(), 2U);
    EXPECT_GE(b.log("laser").falling().size(), 2U);
    EXPECT_GE(b.log("dir_x").edges.size(), 3U);
    EXPECT_GE(b.log("dir_y").edges.size(), 1U);
    EXPECT_EQ(b.fpga.pulse_gen_x.stretched(), 1U);
    // Y stopped between the frame 2 and frame 5 words.
    const auto& ay = b.fpga.applied(1);
    const auto stop = std::find_if(ay.begin(), ay.end(), [](const fpga::AppliedRate& a) { return a.seq == 2; });
    const auto restart = std::find_if(ay.begin(), ay.end(), [](const fpga::AppliedRate& a) { return a.seq == 5; });
    ASSERT_NE(stop, ay.end());
    ASSERT_NE(restart, ay.end());
    EXPECT_EQ(stop->rate.period_cycles, 0U);
    EXPECT_GT(restart->edge - stop->edge, 20'000);
    EXPECT_TRUE(between(rise_edges(b.log("step_y")), stop->edge, restart->edge).empty());
    EXPECT_GT(b.log("step_x").rising().size(), 80U);
    EXPECT_GT(b.log("step_y").rising().size(), 40U);
    EXPECT_NE(b.fpga.count(0), 0);
    EXPECT_NE(b.fpga.count(1), 0);
}

TEST(SpiFpgaRtlIcarus, RatesAtTheNextPulseAsTheModel) {
    SpiFpgaConfig cfg;  // the defaults: depth 4, pulse 100, setup 50, hold 50, AtNextPulse
    SpiBench b("b", SpiConfig{}, cfg, script());
    expect_rtl_as_model(b, cfg);
    if (HasFatalFailure()) return;
    expect_common_coverage(b);
    // The queue filled: frames 11 and 12 dropped, frame 13's reply reports full and dropped.
    const auto& frames = b.fpga.frames();
    EXPECT_TRUE(frames[11].dropped);
    EXPECT_TRUE(frames[12].dropped);
    const SlaveStatus s = decode_status(b.replies()[13][0]);
    EXPECT_TRUE(s.fifo_full);
    EXPECT_TRUE(s.dropped);
    EXPECT_EQ(s.fifo_level, 4U);
}

TEST(SpiFpgaRtlIcarus, RatesAppliedImmediatelyWithOtherParametersAsTheModel) {
    SpiFpgaConfig cfg;
    cfg.rate_apply = RateApply::Immediately;
    cfg.fifo_depth = 2;
    cfg.pulse_cycles = 20;
    cfg.dir_setup_cycles = 7;
    cfg.dir_hold_cycles = 13;
    SpiBench b("b", SpiConfig{}, cfg, script());
    expect_rtl_as_model(b, cfg);
    if (HasFatalFailure()) return;
    expect_common_coverage(b);
    // Frame 1's reversal: read 5 clocks after a rise, DIR waits for the 13-clock hold.
    std::set<std::int64_t> loads;
    for (const auto& a : b.fpga.applied(0)) loads.insert(a.edge);
    const auto dir_changes = change_edges(b.log("dir_x"));
    ASSERT_GE(dir_changes.size(), 2U);
    EXPECT_EQ(dir_changes[1], 21'336 + 8);
    EXPECT_EQ(loads.count(21'336), 1U);
}

TEST(SpiFpgaRtlIcarus, FastestLinkTheSlaveFollowsAsTheModel) {
    // SCLK 8 MHz (half period 62.5 ns, just above the 60 ns the slave needs: check_link), SS to the first SCLK edge and
    // SCLK to SS rise 61 ns, SS high one clock between frames: the synchroniser at the limits of
    // models/fpga/spi/README.md (Decisions), SCLK edges at every phase to the clock.
    SpiConfig link;
    link.sclk_hz = 8'000'000;
    link.cs_setup_ps = 61'000;
    link.cs_hold_ps = 61'000;
    link.ss_idle_min_ps = kCyclePs;
    SpiFpgaConfig cfg;
    fpga::check_link(link, cfg);
    SpiBench b("b", link, cfg, script());
    expect_rtl_as_model(b, cfg);
    if (HasFatalFailure()) return;
    expect_common_coverage(b);
}

}  // namespace
}  // namespace cnc::spi::test
