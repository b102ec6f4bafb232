// SystemC-free cores of the spi-fpga FPGA: pulse generator schedule, FIFO bookkeeping, slave sampling, counter
// register, and the link limits of the oversampling slave.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/bad_input.hpp"
#include "fpga/spi/core/cmd_fifo_core.hpp"
#include "fpga/spi/core/pulse_gen_core.hpp"
#include "fpga/spi/core/spi_fpga_config.hpp"
#include "fpga/spi/core/spi_slave_core.hpp"
#include "fpga/spi/core/step_count_history.hpp"

namespace cnc::fpga {
namespace {

using spi::AxisRate;

struct Change {
    std::int64_t edge;
    char pin;  // 'S' step, 'D' dir
    bool level;
    friend bool operator==(const Change& a, const Change& b) {
        return a.edge == b.edge && a.pin == b.pin && a.level == b.level;
    }
};
std::ostream& operator<<(std::ostream& os, const Change& c) {
    return os << "{" << c.edge << " " << c.pin << (c.level ? "1" : "0") << "}";
}

// Pops every change at an edge < `until`.
std::vector<Change> run_until(PulseGenCore& g, std::int64_t until) {
    std::vector<Change> out;
    for (auto c = g.next_change(); c && c->edge < until; c = g.next_change()) {
        out.push_back({c->edge, c->pin == GenPin::Step ? 'S' : 'D', c->level});
        g.pop();
    }
    return out;
}

SpiFpgaConfig mode(RateApply apply) {
    SpiFpgaConfig cfg;
    cfg.rate_apply = apply;
    return cfg;
}

TEST(PulseGenCore, FirstForwardWordRaisesDirThenStepsAfterSetup) {
    PulseGenCore g(mode(RateApply::Immediately));
    EXPECT_FALSE(g.load(10, {200, true}));
    EXPECT_EQ(run_until(g, 461), (std::vector<Change>{{10, 'D', true},
                                                      {60, 'S', true},
                                                      {160, 'S', false},
                                                      {260, 'S', true},
                                                      {360, 'S', false},
                                                      {460, 'S', true}}));
}

TEST(PulseGenCore, ReverseWordRespectsHoldAndSetupImmediately) {
    PulseGenCore g(mode(RateApply::Immediately));
    (void)g.load(0, {200, true});
    EXPECT_EQ(run_until(g, 270),
              (std::vector<Change>{{0, 'D', true}, {50, 'S', true}, {150, 'S', false}, {250, 'S', true}}));
    // Last rise at 250: DIR may change from 300 (hold 50); the counter compares with the new period at once,
    // so the next rise is max(300 + setup 50, 250 + 200) = 450.
    (void)g.load(270, {200, false});
    EXPECT_EQ(run_until(g, 651),
              (std::vector<Change>{
                  {300, 'D', false}, {350, 'S', false}, {450, 'S', true}, {550, 'S', false}, {650, 'S', true}}));
}

TEST(PulseGenCore, AtNextPulseLoadsOnlyAtTheBoundaryAndRestartsThePeriodThere) {
    PulseGenCore g(mode(RateApply::AtNextPulse));
    EXPECT_TRUE(g.reads_at(5));     // stopped: reads at once
    (void)g.load(0, {200, false});  // DIR already low: first rise at once
    EXPECT_EQ(run_until(g, 1), (std::vector<Change>{{0, 'S', true}}));
    EXPECT_FALSE(g.reads_at(150));
    EXPECT_TRUE(g.reads_at(200));
    EXPECT_EQ(run_until(g, 200), (std::vector<Change>{{100, 'S', false}}));
    (void)g.load(200, {1000, false});  // same direction: the boundary rise stays, then 1000 apart
    EXPECT_EQ(run_until(g, 1201), (std::vector<Change>{{200, 'S', true}, {300, 'S', false}, {1200, 'S', true}}));
    // Reversal at the boundary 2200: DIR at 2200 (hold long over), first rise after setup.
    (void)run_until(g, 2200);
    (void)g.load(2200, {1000, true});
    EXPECT_EQ(run_until(g, 3251),
              (std::vector<Change>{{2200, 'D', true}, {2250, 'S', true}, {2350, 'S', false}, {3250, 'S', true}}));
}

TEST(PulseGenCore, StopKeepsTheRunningPulseAndDir) {
    PulseGenCore g(mode(RateApply::Immediately));
    (void)g.load(0, {300, true});
    (void)run_until(g, 60);        // D 0, S 50 rise
    (void)g.load(60, {0, false});  // stop; the direction of a stop word is ignored
    EXPECT_EQ(run_until(g, 10'000), (std::vector<Change>{{150, 'S', false}}));
    EXPECT_EQ(g.period_cycles(), 0U);
    EXPECT_TRUE(g.dir_level());
    // Restart: spacing from the last rise (50) is the new period.
    (void)g.load(200, {300, true});
    EXPECT_EQ(run_until(g, 351), (std::vector<Change>{{350, 'S', true}}));
}

TEST(PulseGenCore, ShortWordIsStretchedToPulsePlusOneClock) {
    PulseGenCore g(mode(RateApply::Immediately));
    EXPECT_TRUE(g.load(0, {50, false}));
    EXPECT_EQ(g.period_cycles(), 101U);
    EXPECT_EQ(run_until(g, 203),
              (std::vector<Change>{
                  {0, 'S', true}, {100, 'S', false}, {101, 'S', true}, {201, 'S', false}, {202, 'S', true}}));
}

TEST(PulseGenCore, LaterWordCancelsAPendingReversal) {
    PulseGenCore g(mode(RateApply::Immediately));
    (void)g.load(10, {200, true});
    (void)run_until(g, 70);          // D 10, S 60
    (void)g.load(70, {200, false});  // DIR would change at 110
    (void)g.load(100, {200, true});  // back to forward before it did: no DIR edge
    EXPECT_EQ(run_until(g, 261), (std::vector<Change>{{160, 'S', false}, {260, 'S', true}}));
}

TEST(CmdFifoCore, RegisterTimingFullDropAndPerAxisReads) {
    CmdFifoCore f(2, 2);
    const spi::Command r0{{{1000, true}, {2000, false}}, true};
    const spi::Command r1{{{1100, true}, {2100, false}}, false};
    EXPECT_TRUE(f.push(10, 0, r0));
    EXPECT_FALSE(f.readable(0, 10));
    EXPECT_TRUE(f.readable(0, 11));
    EXPECT_EQ(f.level_at(10), 0U);
    EXPECT_EQ(f.level_at(11), 1U);
    EXPECT_TRUE(f.push(20, 1, r1));
    EXPECT_FALSE(f.push(30, 2, r1));  // full: dropped, the FIFO keeps its frames
    EXPECT_EQ(f.drops_before(30), 0U);
    EXPECT_EQ(f.drops_before(31), 1U);

    const auto a = f.read(0, 40);
    ASSERT_TRUE(a.has_value());
    EXPECT_EQ(a->seq, 0U);
    EXPECT_EQ(a->rate, (AxisRate{1000, true}));
    EXPECT_FALSE(a->frame_applied);
    EXPECT_EQ(f.level_at(41), 2U);  // axis 1 has not read it yet
    const auto b = f.read(1, 45);
    ASSERT_TRUE(b.has_value());
    EXPECT_EQ(b->rate, (AxisRate{2000, false}));
    EXPECT_TRUE(b->frame_applied);  // the last axis has its word: the frame (and its laser bit) governs
    EXPECT_TRUE(b->laser_on);
    EXPECT_EQ(f.level_at(45), 2U);  // a read at 45 frees the slot for writes from 46
    EXPECT_FALSE(f.push(45, 3, r0));
    EXPECT_EQ(f.level_at(46), 1U);
    EXPECT_TRUE(f.push(46, 4, r0));

    EXPECT_EQ(f.read(0, 50)->seq, 1U);
    EXPECT_EQ(f.read(0, 51)->seq, 4U);
    EXPECT_FALSE(f.read(0, 52).has_value());  // empty for axis 0
    const auto c = f.read(1, 52);
    ASSERT_TRUE(c.has_value());
    EXPECT_EQ(c->seq, 1U);
    EXPECT_TRUE(c->frame_applied);
    EXPECT_FALSE(c->laser_on);
    EXPECT_EQ(f.read(1, 53)->seq, 4U);
    EXPECT_EQ(f.level_at(54), 0U);

    ASSERT_EQ(f.pushes().size(), 5U);
    EXPECT_EQ(f.pushes()[2].level_before, 2U);
    EXPECT_TRUE(f.pushes()[3].dropped);
    EXPECT_EQ(f.dropped(), 2U);
    EXPECT_EQ(f.max_level(), 2U);
}

TEST(SpiSlaveCore, ByteShiftedInMsbFirstActsTwoEdgesAfterTheSample) {
    SpiSlaveCore s;
    std::vector<SlaveEvent> ev;
    s.sample(5, true, true, false, ev);  // SCLK activity while SS is high is ignored
    s.sample(6, true, false, false, ev);
    EXPECT_TRUE(ev.empty());
    s.sample(10, false, false, true, ev);
    ASSERT_EQ(ev.size(), 1U);
    EXPECT_EQ(ev[0].kind, SlaveEvent::Kind::FrameStart);
    EXPECT_EQ(ev[0].edge, 12);
    const std::uint8_t byte = 0xA5;
    for (int k = 0; k < 8; ++k) {
        const bool bit = ((byte >> (7 - k)) & 1) != 0;
        s.sample(20 + 10 * k, false, true, bit, ev);
        s.sample(25 + 10 * k, false, false, bit, ev);
    }
    s.sample(110, true, false, false, ev);
    ASSERT_EQ(ev.size(), 1U + 8U + 1U);
    for (int k = 0; k < 8; ++k) {
        EXPECT_EQ(ev[1 + k].kind, SlaveEvent::Kind::MisoShift);
        EXPECT_EQ(ev[1 + k].edge, 27 + 10 * k);
        EXPECT_EQ(ev[1 + k].miso_bit, static_cast<std::size_t>(k + 1));
    }
    EXPECT_EQ(ev[9].kind, SlaveEvent::Kind::FrameEnd);
    EXPECT_EQ(ev[9].edge, 112);
    EXPECT_EQ(ev[9].mosi_bits, 8U);
    EXPECT_EQ(ev[9].mosi, std::vector<std::uint8_t>{0xA5});
}

TEST(SpiSlaveCore, PartialByteIsCountedButNotHandedOver) {
    SpiSlaveCore s;
    std::vector<SlaveEvent> ev;
    s.sample(1, false, false, false, ev);
    for (int k = 0; k < 12; ++k) {
        s.sample(10 + 4 * k, false, true, true, ev);
        s.sample(12 + 4 * k, false, false, true, ev);
    }
    s.sample(100, true, false, false, ev);
    EXPECT_EQ(ev.back().mosi_bits, 12U);
    EXPECT_EQ(ev.back().mosi, std::vector<std::uint8_t>{0xFF});
    EXPECT_EQ(s.select(200).edge, 202);
    const SlaveEvent end = s.deselect(300, {0x52, 0x01});
    EXPECT_EQ(end.edge, 302);
    EXPECT_EQ(end.mosi_bits, 16U);
}

TEST(StepCountHistory, LoadAtEdgeMSeesRisesUpToMMinusTwo) {
    StepCountHistory h;
    h.add_rise(100, true);
    EXPECT_EQ(h.value_at_edge(101), 0);
    EXPECT_EQ(h.value_at_edge(102), 1);
    h.add_rise(200, false);
    h.add_rise(300, false);
    EXPECT_EQ(h.value_at_edge(202), 0);
    EXPECT_EQ(h.value_at_edge(302), -1);  // 0xFFFFFFFF: wraps like the 32-bit register
    EXPECT_EQ(h.value(), -1);
    EXPECT_EQ(h.forward_rises(), 1U);
    EXPECT_EQ(h.reverse_rises(), 2U);
    for (int k = 0; k < 6; ++k) h.add_rise(1000 + 10 * k, true);  // updates at 1001..1051, values 0..5
    EXPECT_EQ(h.value_at_edge(1025), 2);                          // update at 1021
    EXPECT_EQ(h.value_at_edge(1015), 1);                          // older than the kept updates
    EXPECT_EQ(h.value_at_edge(1060), 5);
}

TEST(SpiFpgaConfig, LinkLimitsOfTheOversamplingSlave) {
    const SpiFpgaConfig cfg;
    spi::SpiConfig link;
    EXPECT_NO_THROW(check_link(link, cfg));
    EXPECT_EQ(max_sclk_hz(cfg), 8'333'194U);  // half period >= 60 001 ps
    link.sclk_hz = 8'333'194;
    EXPECT_NO_THROW(check_link(link, cfg));
    link.sclk_hz = 8'333'195;
    EXPECT_THROW(check_link(link, cfg), BadInput);
    link.sclk_hz = 10'000'000;
    try {
        check_link(link, cfg);
        FAIL() << "no BadInput";
    } catch (const BadInput& e) {
        const std::string msg = e.what();
        EXPECT_EQ(msg.rfind("spi: sclk_hz: SCLK 10000000 Hz is too fast", 0), 0U) << msg;
        EXPECT_NE(msg.find("highest usable rate is 8333194 Hz"), std::string::npos) << msg;
    }
    link = spi::SpiConfig{};
    link.cs_setup_ps = 60'000;
    EXPECT_THROW(check_link(link, cfg), BadInput);
    link.cs_setup_ps = 60'001;
    EXPECT_NO_THROW(check_link(link, cfg));
    link.ss_idle_min_ps = 19'999;
    EXPECT_THROW(check_link(link, cfg), BadInput);
}

TEST(SpiFpgaConfig, ValidateNamesTheKey) {
    EXPECT_NO_THROW(validate(SpiFpgaConfig{}));
    EXPECT_EQ(min_period_cycles(SpiFpgaConfig{}), 101U);
    SpiFpgaConfig c;
    c.fifo_depth = 0;
    EXPECT_THROW(validate(c), BadInput);
    c = SpiFpgaConfig{};
    c.dir_hold_cycles = 0;
    try {
        validate(c);
        FAIL() << "no BadInput";
    } catch (const BadInput& e) {
        EXPECT_EQ(std::string(e.what()).rfind("fpga: dir_hold_cycles: ", 0), 0U) << e.what();
    }
    c = SpiFpgaConfig{};
    c.clk_hz = 48'000'000;  // 20 833.3 ps
    EXPECT_THROW(validate(c), BadInput);
}

}  // namespace
}  // namespace cnc::fpga
