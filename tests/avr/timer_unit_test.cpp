// TimerUnit against the datasheet (§15 Timer0, §16 Timer1, §17 prescalers, §18 Timer2) and against a
// tick-by-tick reference (the unit itself only steps the ticks where something happens).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "avr/core/timer_unit.hpp"

using namespace cnc::avr;

namespace {

struct FlagEvent {
    TimerFlag flag;
    Cycle cycle;
    friend bool operator==(const FlagEvent& a, const FlagEvent& b) { return a.flag == b.flag && a.cycle == b.cycle; }
    friend void PrintTo(const FlagEvent& e, std::ostream* os) {
        *os << "flag" << static_cast<int>(e.flag) << "@" << e.cycle;
    }
};

// Effective compare output pins (0 when disconnected), recorded when they change.
struct PinState {
    Cycle cycle;
    bool a;
    bool b;
    friend bool operator==(const PinState& x, const PinState& y) {
        return x.cycle == y.cycle && x.a == y.a && x.b == y.b;
    }
    friend void PrintTo(const PinState& p, std::ostream* os) { *os << p.a << p.b << "@" << p.cycle; }
};

// Appends the pin state at cycle c if it differs; several changes within one cycle (A, then B) count as one,
// which is what a pin sampler sees.
void note_pins(std::vector<PinState>& pins, Cycle c, bool a, bool b) {
    if (!pins.empty() && pins.back().cycle == c) pins.pop_back();
    const bool before_a = !pins.empty() && pins.back().a;
    const bool before_b = !pins.empty() && pins.back().b;
    if (before_a != a || before_b != b) pins.push_back({c, a, b});
}

class Recorder : public TimerSink {
public:
    void timer_flag(char, TimerFlag flag, Cycle c) override { flags.push_back({flag, c}); }
    void timer_output(char, Cycle c) override {
        if (unit == nullptr) return;
        const bool a = unit->output_connected(Channel::A) && unit->output_level(Channel::A);
        const bool b = unit->output_connected(Channel::B) && unit->output_level(Channel::B);
        note_pins(pins, c, a, b);
    }
    [[nodiscard]] std::vector<Cycle> flag_cycles(TimerFlag f) const {
        std::vector<Cycle> out;
        for (const auto& e : flags)
            if (e.flag == f) out.push_back(e.cycle);
        return out;
    }
    const TimerUnit* unit = nullptr;
    std::vector<FlagEvent> flags;
    std::vector<PinState> pins;
};

struct Fixture {
    explicit Fixture(const TimerSpec& spec) : unit(spec, prescaler, rec) { rec.unit = &unit; }
    Prescaler prescaler;
    Recorder rec;
    TimerUnit unit;
};

std::vector<Cycle> toggle_cycles(const std::vector<PinState>& pins) {
    std::vector<Cycle> out;
    for (const auto& p : pins) out.push_back(p.cycle);
    return out;
}

}  // namespace

TEST(AvrTimerUnit, Timer1CtcPeriodIsOcrPlusOneTicks) {
    // Timer1 mode 4 (CTC, TOP = OCR1A = 1599), N = 1, COM1A = toggle: OCF1A and a toggle every 1600 cycles
    // (the 10 kHz ISR of firmware/tests/bench_idle.c), first at start + 1600.
    Fixture f(kTimer1);
    f.unit.write_ocr(0, Channel::A, 1599);
    f.unit.write_tccra(0, 0x40);        // COM1A0
    f.unit.write_tccrb(100, 0x08 | 1);  // WGM12, CS10
    EXPECT_EQ(f.unit.read_tcnt(100 + 1600 + 37), 37);
    f.unit.advance_to(100 + 5 * 1600);
    EXPECT_EQ(f.rec.flag_cycles(TimerFlag::CompareA), (std::vector<Cycle>{1700, 3300, 4900, 6500, 8100}));
    EXPECT_EQ(toggle_cycles(f.rec.pins), (std::vector<Cycle>{1700, 3300, 4900, 6500, 8100}));
    EXPECT_TRUE(f.rec.flag_cycles(TimerFlag::Overflow).empty());  // CTC: TOV1 only at MAX
    // Event-driven: 10 stepped ticks of 8000 (5 compare A matches, and 5 compare B matches: OCR1B = 0).
    EXPECT_EQ(f.unit.event_ticks(), 10U);
}

TEST(AvrTimerUnit, NormalModeOverflowsEvery256TicksAndTcntFollowsTheTicks) {
    // Timer0 Normal mode, N = 8 from the free-running prescaler (ticks at multiples of 8 after the write):
    // TOV0 at the tick that leaves 0xFF, every 256 * 8 = 2048 cycles.
    Fixture f(kTimer0);
    f.unit.write_tccrb(3, 2);  // CS01: /8; first tick at cycle 8
    f.unit.advance_to(3 + 3 * 2048 + 100);
    EXPECT_EQ(f.rec.flag_cycles(TimerFlag::Overflow), (std::vector<Cycle>{2048, 4096, 6144}));
    EXPECT_EQ(f.rec.flag_cycles(TimerFlag::CompareA), (std::vector<Cycle>{8, 2056, 4104, 6152}));  // OCR0A = 0
    Fixture g(kTimer0);
    g.unit.write_tccrb(3, 2);
    EXPECT_EQ(g.unit.read_tcnt(7), 0);
    EXPECT_EQ(g.unit.read_tcnt(8), 1);
    EXPECT_EQ(g.unit.read_tcnt(15), 1);
    EXPECT_EQ(g.unit.read_tcnt(16), 2);
    EXPECT_EQ(g.unit.read_tcnt(2047), 255);
    EXPECT_EQ(g.unit.read_tcnt(2048), 0);
}

TEST(AvrTimerUnit, StoppedTimerKeepsItsCount) {
    Fixture f(kTimer2);
    f.unit.write_tccrb(0, 1);
    EXPECT_EQ(f.unit.read_tcnt(50), 50);
    f.unit.write_tccrb(50, 0);  // stop
    EXPECT_EQ(f.unit.read_tcnt(5000), 50);
    EXPECT_FALSE(f.unit.next_event().has_value());
    f.unit.write_tccrb(6000, 1);
    EXPECT_EQ(f.unit.read_tcnt(6010), 60);
}

TEST(AvrTimerUnit, FastPwmDutyIsOcrPlusOneOver256) {
    // Timer0 mode 3 (fast PWM, TOP = 0xFF), COM0A = 10 (non-inverting), OCR0A = 63, N = 1: OC0A set at BOTTOM
    // (the tick leaving 0xFF), cleared at the tick leaving 63: high for 64 of every 256 cycles.
    Fixture f(kTimer0);
    f.unit.write_ocr(0, Channel::A, 63);
    f.unit.write_tccra(0, 0x80 | 0x03);
    f.unit.write_tccrb(0, 1);
    f.unit.advance_to(4 * 256);
    // OC0A resets to 0, so the clear at 64 changes nothing; then high at 256, low at 320, ...
    EXPECT_EQ(toggle_cycles(f.rec.pins), (std::vector<Cycle>{256, 320, 512, 576, 768, 832, 1024}));
    EXPECT_TRUE(f.rec.pins.front().a);
    EXPECT_EQ(f.rec.flag_cycles(TimerFlag::Overflow), (std::vector<Cycle>{256, 512, 768, 1024}));
}

TEST(AvrTimerUnit, FastPwmOcrIsDoubleBufferedUntilBottom) {
    Fixture f(kTimer0);
    f.unit.write_ocr(0, Channel::A, 63);
    f.unit.write_tccra(0, 0x80 | 0x03);
    f.unit.write_tccrb(0, 1);
    f.unit.write_ocr(100, Channel::A, 127);  // takes effect at BOTTOM (cycle 256)
    EXPECT_EQ(f.unit.ocr(Channel::A), 127);  // the CPU reads the buffer
    f.unit.advance_to(600);
    EXPECT_EQ(toggle_cycles(f.rec.pins), (std::vector<Cycle>{256, 384, 512}));
}

TEST(AvrTimerUnit, PhaseCorrectPeriodIsTwiceTopAndDutyOcrOverTop) {
    // Timer0 mode 1 (phase correct, TOP = 0xFF), COM0A = 10, OCR0A = 64, N = 1: period 2 * 255 = 510 cycles;
    // cleared when the count leaves 64 going up (cycle 65), set when it leaves 64 going down (446 + 1 = 447):
    // high for 2 * 64 = 128 of 510 cycles. TOV0 at BOTTOM: the tick that leaves 0 after counting down (511).
    Fixture f(kTimer0);
    f.unit.write_ocr(0, Channel::A, 64);
    f.unit.write_tccra(0, 0x80 | 0x01);
    f.unit.write_tccrb(0, 1);
    f.unit.advance_to(1100);
    EXPECT_EQ(toggle_cycles(f.rec.pins), (std::vector<Cycle>{447, 575, 957, 1085}));
    EXPECT_EQ(f.rec.flag_cycles(TimerFlag::Overflow), (std::vector<Cycle>{511, 1021}));
}

TEST(AvrTimerUnit, Timer1FastPwmWithIcr1Top) {
    // Timer1 mode 14 (fast PWM, TOP = ICR1 = 39 999, N = 8: the 50 Hz servo frame), COM1A = 10, OCR1A = 2999:
    // high for (2999 + 1) * 8 = 24 000 cycles (1.5 ms) of every 40 000 * 8 = 320 000 (20 ms); ICF1 and TOV1 at TOP.
    Fixture f(kTimer1);
    f.unit.write_icr(0, 39'999);
    f.unit.write_ocr(0, Channel::A, 2999);
    f.unit.write_tccra(0, 0x80 | 0x02);  // COM1A1, WGM11
    f.unit.write_tccrb(0, 0x18 | 0x02);  // WGM13:12, CS11 (/8, first tick at 8)
    f.unit.advance_to(2 * 320'000 + 100);
    EXPECT_EQ(toggle_cycles(f.rec.pins), (std::vector<Cycle>{320'000, 344'000, 640'000}));
    EXPECT_EQ(f.rec.flag_cycles(TimerFlag::Overflow), (std::vector<Cycle>{320'000, 640'000}));
    EXPECT_EQ(f.rec.flag_cycles(TimerFlag::Capture), (std::vector<Cycle>{320'000, 640'000}));
    EXPECT_EQ(f.rec.flag_cycles(TimerFlag::CompareA), (std::vector<Cycle>{24'000, 344'000}));
}

TEST(AvrTimerUnit, TcntWriteBlocksTheNextCompareMatch) {
    // §15.5.2: a TCNT0 write blocks the compare match of the next timer clock. CTC, OCR0A = 10, N = 1, stopped
    // with TCNT0 = 10: the first tick after the start leaves 10 without a match (the CTC clear still happens),
    // so the first OCF0A comes 11 ticks later.
    Fixture f(kTimer0);
    f.unit.write_ocr(0, Channel::A, 10);
    f.unit.write_tccra(0, 0x42);
    f.unit.write_tcnt(0, 10);
    f.unit.write_tccrb(100, 1);
    f.unit.advance_to(140);
    EXPECT_EQ(f.rec.flag_cycles(TimerFlag::CompareA), (std::vector<Cycle>{112, 123, 134}));
    // Without the write (TCNT0 = 10 reached by counting) the match is not blocked.
    Fixture g(kTimer0);
    g.unit.write_ocr(0, Channel::A, 10);
    g.unit.write_tccra(0, 0x42);
    g.unit.write_tccrb(100, 1);
    g.unit.advance_to(140);
    EXPECT_EQ(g.rec.flag_cycles(TimerFlag::CompareA), (std::vector<Cycle>{111, 122, 133}));
}

TEST(AvrTimerUnit, ForceOutputCompareTogglesWithoutAFlag) {
    Fixture f(kTimer2);
    f.unit.write_ocr(0, Channel::A, 200);
    f.unit.write_tccra(0, 0x42);
    f.unit.write_tccrb(10, 0x80);  // FOC2A with the clock stopped
    EXPECT_TRUE(f.unit.output_level(Channel::A));
    EXPECT_TRUE(f.rec.flags.empty());
    EXPECT_EQ(f.unit.tccrb(), 0);  // FOC reads as zero
    f.unit.write_tccra(20, 0x83);  // fast PWM: FOC is ignored
    f.unit.write_tccrb(21, 0x80);
    EXPECT_TRUE(f.unit.output_level(Channel::A));
}

TEST(AvrTimerUnit, PrescalerHeldByTsmStopsPrescaledClocksOnly) {
    // §17.4.1: GTCCR = TSM | PSRSYNC holds the Timer0/1 prescaler in reset; clk/1 is not prescaled and runs on.
    Prescaler p;
    Recorder r0;
    Recorder r1;
    TimerUnit t0(kTimer0, p, r0);
    TimerUnit t1(kTimer1, p, r1);
    t0.write_tccrb(0, 2);  // /8
    t1.write_tccrb(0, 1);  // /1
    p.hold(5);             // the units are at cycle <= 5
    EXPECT_EQ(t0.read_tcnt(1000), 0);
    EXPECT_EQ(t1.read_tcnt(1000), 1000);
    t0.advance_to(1003);
    t1.advance_to(1003);
    p.release(1003);  // counts from 0 again at 1003: /8 ticks at 1011, 1019, ...
    EXPECT_EQ(t0.read_tcnt(1010), 0);
    EXPECT_EQ(t0.read_tcnt(1011), 1);
    EXPECT_EQ(t0.read_tcnt(1003 + 8 * 100), 100);
}

namespace {

// The datasheet rules of timer_unit.hpp, applied at every tick of every cycle (all timers, all modes).
class ReferenceTimer {
public:
    explicit ReferenceTimer(const TimerSpec& spec) : m_spec(spec), m_max(spec.sixteen_bit ? 0xFFFF : 0xFF) {}
    std::uint8_t tccra = 0;
    std::uint8_t tccrb = 0;
    int tcnt = 0;
    bool up = true;
    bool block = false;
    int ocr[2] = {0, 0};
    int buf[2] = {0, 0};
    int icr = 0;
    bool oc[2] = {false, false};
    std::vector<FlagEvent> flags;
    std::vector<PinState> pins;

    [[nodiscard]] TimerMode mode() const {
        return m_spec.sixteen_bit ? timer_mode_16bit((tccra & 3U) | ((tccrb >> 1) & 0x0CU))
                                  : timer_mode_8bit((tccra & 3U) | ((tccrb >> 1) & 4U));
    }
    [[nodiscard]] int divisor() const { return m_spec.divisors[tccrb & 7U]; }
    [[nodiscard]] CompareOutput out(int ch) const {
        return compare_output(mode(), (tccra >> (ch == 0 ? 6 : 4)) & 3U, ch == 0);
    }
    [[nodiscard]] int top() const {
        const TimerMode m = mode();
        if (m.top_source == TopSource::OcrA) return ocr[0];
        if (m.top_source == TopSource::Icr) return icr;
        return std::min<int>(m.fixed_top, m_max);
    }
    void act(int ch, OcAction a) {
        if (a == OcAction::Toggle) oc[ch] = !oc[ch];
        if (a == OcAction::Clear) oc[ch] = false;
        if (a == OcAction::Set) oc[ch] = true;
    }
    void tick_if_due(Cycle c) {
        const int n = divisor();
        if (n <= 0 || c % n != 0) return;  // prescaler origin 0, never held
        const TimerMode m = mode();
        const int t = top();
        const int v = tcnt;
        const bool match[2] = {!block && v == ocr[0], !block && v == ocr[1]};
        block = false;
        bool step_up = true;
        bool wrap = false;
        bool tov = false;
        bool at_top = false;
        bool at_bottom = false;
        if (m.single_slope() || v > t) {
            up = true;
            wrap = v == t || v == m_max;
            at_top = v == t;
            tcnt = wrap ? 0 : v + 1;
            // TOV: Normal/CTC at MAX, fast PWM at TOP; a dual-slope counter running away above TOP sets none
            tov = m.wave == Wave::FastPwm ? wrap : m.single_slope() && v == m_max;
        } else if (t == 0) {  // TOP = BOTTOM: the counter stays at 0, both turning points at every tick
            at_top = at_bottom = tov = true;
        } else if (up) {
            at_top = v == t;
            step_up = !at_top;
            up = !at_top;
            tcnt = at_top ? v - 1 : v + 1;
        } else {
            at_bottom = v == 0;
            step_up = at_bottom;
            up = at_bottom;
            tcnt = at_bottom ? 1 : v - 1;
            tov = at_bottom;
        }
        for (int ch = 0; ch < 2; ++ch)
            if (match[ch]) act(ch, step_up ? out(ch).on_match_up : out(ch).on_match_down);
        if (m.wave == Wave::FastPwm && wrap)
            for (int ch = 0; ch < 2; ++ch) act(ch, out(ch).at_bottom);
        if (match[0]) flags.push_back({TimerFlag::CompareA, c});
        if (match[1]) flags.push_back({TimerFlag::CompareB, c});
        if (tov) flags.push_back({TimerFlag::Overflow, c});
        if (at_top && m.top_source == TopSource::Icr) flags.push_back({TimerFlag::Capture, c});
        if ((m.ocr_update == OcrUpdate::AtBottom && ((wrap && m.single_slope()) || at_bottom)) ||
            (m.ocr_update == OcrUpdate::AtTop && at_top)) {
            ocr[0] = buf[0];
            ocr[1] = buf[1];
        }
        note(c);
    }
    void note(Cycle c) { note_pins(pins, c, out(0).connected && oc[0], out(1).connected && oc[1]); }
    void write_ocr(int ch, int v) {
        buf[ch] = v;
        if (!mode().pwm()) ocr[ch] = v;
    }
    void after_mode_change(Cycle c) {
        if (!mode().pwm()) {
            ocr[0] = buf[0];
            ocr[1] = buf[1];
        }
        note(c);
    }

private:
    TimerSpec m_spec;
    int m_max;
};

template <typename T>
std::string first_difference(const std::vector<T>& got, const std::vector<T>& want) {
    for (std::size_t i = 0; i < std::max(got.size(), want.size()); ++i) {
        if (i < got.size() && i < want.size() && got[i] == want[i]) continue;
        return "at " + std::to_string(i) + ": got " +
               (i < got.size() ? ::testing::PrintToString(got[i]) : std::string("nothing")) + ", want " +
               (i < want.size() ? ::testing::PrintToString(want[i]) : std::string("nothing"));
    }
    return "";
}

// A unit and the reference for one seed of the random tests: Timer0, 1 or 2 by the seed.
struct RandomBench {
    explicit RandomBench(unsigned seed)
        : rng(seed), spec(*kSpecs[seed % 3]), unit(spec, prescaler, rec), ref(spec) {
        rec.unit = &unit;
    }
    int pick(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
    // A register written to both at cycle c.
    void write_ocr(Cycle c, Channel ch, int v) {
        unit.write_ocr(c, ch, static_cast<std::uint16_t>(v));
        ref.write_ocr(ch == Channel::A ? 0 : 1, v);
    }
    void write_tccra(Cycle c, std::uint8_t v) {
        unit.write_tccra(c, v);
        ref.tccra = v;
        ref.after_mode_change(c);
    }
    void write_tccrb(Cycle c, std::uint8_t v) {
        unit.write_tccrb(c, v);
        ref.tccrb = v;
        ref.after_mode_change(c);
    }
    static constexpr const TimerSpec* kSpecs[3] = {&kTimer0, &kTimer1, &kTimer2};
    std::mt19937 rng;
    const TimerSpec& spec;
    Prescaler prescaler;
    Recorder rec;
    TimerUnit unit;
    ReferenceTimer ref;
};

}  // namespace

TEST(AvrTimerUnit, MatchesATickByTickReferenceUnderRandomRegisterWrites) {
    for (unsigned seed = 1; seed <= 600; ++seed) {
        RandomBench bench(seed);
        const TimerSpec& spec = bench.spec;
        TimerUnit& unit = bench.unit;
        Recorder& rec = bench.rec;
        ReferenceTimer& ref = bench.ref;
        const auto pick = [&](int lo, int hi) { return bench.pick(lo, hi); };
        // (cycle, register, value): 0 OCRA, 1 OCRB, 2 TCNT, 3 TCCRA, 4 TCCRB, 5 ICR, 6 read TCNT. 16-bit values
        // stay below 0x400 so that 30 000 cycles see many periods.
        std::vector<std::tuple<Cycle, int, int>> writes;
        for (Cycle c = 1; c < 30'000; c += pick(1, 1500))
            writes.emplace_back(c, pick(0, 6), spec.sixteen_bit ? pick(0, 0x3FF) : pick(0, 0xFF));
        std::vector<int> unit_reads;
        std::vector<int> ref_reads;
        std::size_t next = 0;
        for (Cycle c = 1; c <= 30'000; ++c) {
            ref.tick_if_due(c);
            for (; next < writes.size() && std::get<0>(writes[next]) == c; ++next) {
                const int reg = std::get<1>(writes[next]);
                int v = std::get<2>(writes[next]);
                if (reg == 3) v &= 0xF3;                                                // COMnA, COMnB, WGMn1:0
                if (reg == 4) v = (v & (spec.sixteen_bit ? 0x18 : 0x08)) | pick(1, 2);  // WGM bits, clock /1 or /8
                const auto u16 = static_cast<std::uint16_t>(v);
                switch (reg) {
                    case 0:
                        bench.write_ocr(c, Channel::A, v);
                        break;
                    case 1:
                        bench.write_ocr(c, Channel::B, v);
                        break;
                    case 2:
                        unit.write_tcnt(c, u16);
                        ref.tcnt = v;
                        ref.block = true;
                        break;
                    case 3:
                        bench.write_tccra(c, static_cast<std::uint8_t>(v));
                        break;
                    case 4:
                        bench.write_tccrb(c, static_cast<std::uint8_t>(v));
                        break;
                    case 5:
                        if (spec.sixteen_bit) {
                            unit.write_icr(c, u16);
                            ref.icr = v;
                        }
                        break;
                    default:
                        unit_reads.push_back(unit.read_tcnt(c));
                        ref_reads.push_back(ref.tcnt);
                        break;
                }
            }
        }
        unit.advance_to(30'000);
        ASSERT_EQ(unit_reads, ref_reads) << "seed " << seed;
        ASSERT_EQ(first_difference(rec.flags, ref.flags), "") << "seed " << seed;
        ASSERT_EQ(first_difference(rec.pins, ref.pins), "") << "seed " << seed;
        EXPECT_EQ(unit.read_tcnt(30'000), ref.tcnt) << "seed " << seed;
    }
}

// The same random register writes with the owner's flag register modelled here: a flag is set when raised and
// cleared now and then, its interrupt enabled now and then, and the unit told which flags are quiet (set, interrupt
// disabled) after each of its events and each change, as the chip does. The unit must report exactly the
// reference's raises of flags that were not quiet when raised (a quiet raise changes nothing: reporting one is
// allowed), read the reference's TCNT and drive its pins, while it runs the quiet periods in closed form (grbl leaves Timer1 in CTC with OCR1A = 0 at /1 when idle: a match at
// every clock).
TEST(AvrTimerUnit, QuietFlagsChangeNothingButWhatIsReported) {
    std::uint64_t stepped = 0;
    std::uint64_t flag_ticks = 0;
    for (unsigned seed = 1; seed <= 300; ++seed) {
        RandomBench bench(seed);
        const TimerSpec& spec = bench.spec;
        TimerUnit& unit = bench.unit;
        Recorder& rec = bench.rec;
        ReferenceTimer& ref = bench.ref;
        const auto pick = [&](int lo, int hi) { return bench.pick(lo, hi); };
        std::array<bool, 4> set{};      // by TimerFlag
        std::array<bool, 4> enabled{};  // by TimerFlag
        const auto mask = [&] {
            unsigned m = 0;
            for (unsigned f = 0; f < 4; ++f)
                if (set[f] && !enabled[f]) m |= 1U << f;
            return static_cast<std::uint8_t>(m);
        };
        std::vector<FlagEvent> want;          // the reference's raises of flags that were not quiet
        std::vector<FlagEvent> quiet_raises;  // and of those that were: the unit may report them or not
        std::size_t ref_seen = 0;
        std::vector<int> unit_reads;
        std::vector<int> ref_reads;
        for (Cycle c = 1; c <= 30'000; ++c) {
            ref.tick_if_due(c);
            for (; ref_seen < ref.flags.size(); ++ref_seen) {
                const FlagEvent& e = ref.flags[ref_seen];
                const auto f = static_cast<std::size_t>(e.flag);
                (set[f] && !enabled[f] ? quiet_raises : want).push_back(e);
                set[f] = true;
            }
            for (auto e = unit.next_event(); e && *e <= c; e = unit.next_event()) {
                unit.advance_to(*e);
                unit.set_quiet_flags(*e, mask());
            }
            if (pick(0, 400) == 0) {
                const int op = pick(0, 4);
                const int v = spec.sixteen_bit ? pick(0, 0x3FF) : pick(0, 0xFF);
                if (op == 0) {
                    bench.write_ocr(c, Channel::A, v);
                } else if (op == 1) {
                    bench.write_ocr(c, Channel::B, v);
                } else if (op == 2) {
                    const int wgm = pick(0, 3);  // Normal, CTC, fast PWM (8-bit), fast PWM TOP = OCRA or ICR1
                    const std::uint8_t com = pick(0, 3) == 0 ? static_cast<std::uint8_t>(pick(0, 15) << 4) : 0;
                    const std::uint8_t a = static_cast<std::uint8_t>(com | (wgm >= 2 ? 1 : 0) | (wgm == 3 ? 2 : 0));
                    std::uint8_t b = static_cast<std::uint8_t>(pick(1, 2));  // clock /1 or /8
                    if (wgm == 1) b |= 0x08;                                 // WGMn2 / WGM12: CTC
                    if (wgm == 3) b |= spec.sixteen_bit ? 0x18 : 0x08;
                    bench.write_tccra(c, a);
                    bench.write_tccrb(c, b);
                } else if (op == 3) {
                    set[static_cast<std::size_t>(pick(0, 3))] = false;  // TIFRn written with a one
                } else {
                    const auto f = static_cast<std::size_t>(pick(0, 3));
                    enabled[f] = !enabled[f];
                }
                unit.set_quiet_flags(c, mask());
            }
            if (pick(0, 700) == 0) {
                unit_reads.push_back(unit.read_tcnt(c));
                ref_reads.push_back(ref.tcnt);
            }
        }
        unit.advance_to(30'000);
        ASSERT_EQ(unit_reads, ref_reads) << "seed " << seed;
        std::vector<FlagEvent> got;
        for (const FlagEvent& e : rec.flags)
            if (std::find(quiet_raises.begin(), quiet_raises.end(), e) == quiet_raises.end()) got.push_back(e);
        ASSERT_EQ(first_difference(got, want), "") << "seed " << seed;
        ASSERT_EQ(first_difference(rec.pins, ref.pins), "") << "seed " << seed;
        EXPECT_EQ(unit.read_tcnt(30'000), ref.tcnt) << "seed " << seed;
        stepped += unit.event_ticks();
        for (std::size_t i = 0; i < ref.flags.size(); ++i)
            if (i == 0 || ref.flags[i].cycle != ref.flags[i - 1].cycle) ++flag_ticks;
    }
    // The quiet periods were taken: a unit stepping every tick that raises a flag steps at least flag_ticks.
    EXPECT_LT(stepped, flag_ticks);
}

// grbl 1.1's idle stepper timer (stepper.c st_go_idle: Timer1 in CTC at /1, OCR1A never written: 0): TOP = 0, a
// compare match A and B at every clock. Once OCF1A and OCF1B are set with their interrupts disabled, a second of
// it is no stepped tick; clearing OCF1A makes the very next clock an event again, which raises it.
TEST(AvrTimerUnit, IdleCtcAtTopZeroIsNotSteppedWhileItsFlagsAreQuiet) {
    Fixture f(kTimer1);
    f.unit.write_tccrb(0, 0x08 | 1);  // WGM12, CS10
    f.unit.advance_to(1);
    EXPECT_EQ(f.rec.flag_cycles(TimerFlag::CompareA), (std::vector<Cycle>{1}));
    const std::uint8_t a_and_b =
        (1U << static_cast<unsigned>(TimerFlag::CompareA)) | (1U << static_cast<unsigned>(TimerFlag::CompareB));
    f.unit.set_quiet_flags(1, a_and_b);
    const std::uint64_t stepped = f.unit.event_ticks();
    EXPECT_FALSE(f.unit.next_event().has_value());
    EXPECT_EQ(f.unit.read_tcnt(16'000'000), 0);
    EXPECT_EQ(f.unit.event_ticks(), stepped);
    f.unit.set_quiet_flags(16'000'000, 1U << static_cast<unsigned>(TimerFlag::CompareB));
    EXPECT_EQ(f.unit.next_event(), std::optional<Cycle>(16'000'001));
    f.unit.advance_to(16'000'001);
    EXPECT_EQ(f.rec.flag_cycles(TimerFlag::CompareA), (std::vector<Cycle>{1, 16'000'001}));
}

// grbl 1.1's stepper timer (stepper.c: Timer1 in CTC at /1, OCR1A the step period, OCR1B never written: 0): OCF1B
// is raised at the tick after each OCF1A and, with its interrupt disabled, stays set. Once it is quiet its matches
// are no events: a period is one stepped tick (the A match), the count between is taken in closed form.
TEST(AvrTimerUnit, QuietMatchBetweenEnabledMatchesIsNotStepped) {
    Fixture f(kTimer1);
    f.unit.write_ocr(0, Channel::A, 1599);
    f.unit.write_tccrb(100, 0x08 | 1);  // WGM12, CS10
    f.unit.advance_to(101);
    EXPECT_EQ(f.rec.flag_cycles(TimerFlag::CompareB), (std::vector<Cycle>{101}));  // the tick that leaves 0
    f.unit.set_quiet_flags(101, 1U << static_cast<unsigned>(TimerFlag::CompareB));
    f.unit.advance_to(100 + 5 * 1600);
    EXPECT_EQ(f.rec.flag_cycles(TimerFlag::CompareA), (std::vector<Cycle>{1700, 3300, 4900, 6500, 8100}));
    EXPECT_EQ(f.rec.flag_cycles(TimerFlag::CompareB), (std::vector<Cycle>{101}));
    EXPECT_EQ(f.unit.event_ticks(), 1U + 5U);
    EXPECT_EQ(f.unit.read_tcnt(8100 + 37), 37);
}

// grbl 1.1's step pulse (stepper.c: TCNT0 = 240 for a 10 us pulse, TCCR0B = CS01, TOIE0 on; OCR0A = OCR0B = 0 with
// OCF0A/OCF0B set and disabled): the TCNT0 write blocks the next tick's match (§15.5.2), but 240 is no compare value,
// so that tick is no event; nor is the quiet match at 0 after the wrap. Clock edges every 8 cycles from cycle 0
// (the prescaler runs free): ticks at 104, 112, ...; the 16th (224) leaves 255 and raises TOV0; by 300, 25 ticks.
TEST(AvrTimerUnit, TcntWriteAwayFromTheCompareValuesIsNoEvent) {
    Fixture f(kTimer0);
    const std::uint8_t a_and_b =
        (1U << static_cast<unsigned>(TimerFlag::CompareA)) | (1U << static_cast<unsigned>(TimerFlag::CompareB));
    f.unit.set_quiet_flags(0, a_and_b);
    f.unit.write_tcnt(100, 240);
    f.unit.write_tccrb(100, 2);  // CS01
    f.unit.advance_to(300);
    EXPECT_EQ(f.rec.flag_cycles(TimerFlag::Overflow), (std::vector<Cycle>{224}));
    EXPECT_TRUE(f.rec.flag_cycles(TimerFlag::CompareA).empty());
    EXPECT_EQ(f.unit.event_ticks(), 1U);
    EXPECT_EQ(f.unit.read_tcnt(300), (240 + 25) % 256);
}

// Every clock select code against the datasheet's tables (Table 15-9 Timer0, 16-5 Timer1: /1 /8 /64 /256 /1024,
// CS = 110/111 the external T0/T1 pin; Table 18-9 Timer2: /1 /8 /32 /64 /128 /256 /1024). With the prescaler
// counting from cycle 0 and the clock selected at cycle 0, tap N ticks at N, 2N, ...: TCNT is k at cycle k N
// and still k - 1 one cycle earlier (the boundary cycle shows an N off by one as well as a wrong tap).
TEST(AvrTimerUnit, EveryClockSelectCodeDividesByTheDatasheetsFactor) {
    struct Case {
        const TimerSpec* spec;
        std::uint8_t cs;
        int n;  // 0: no internal clock (stopped, or the external pin, which nothing drives here)
    };
    const Case cases[] = {
        {&kTimer0, 0, 0},    {&kTimer0, 1, 1},    {&kTimer0, 2, 8},    {&kTimer0, 3, 64},  {&kTimer0, 4, 256},
        {&kTimer0, 5, 1024}, {&kTimer0, 6, 0},    {&kTimer0, 7, 0},    {&kTimer1, 1, 1},   {&kTimer1, 2, 8},
        {&kTimer1, 3, 64},   {&kTimer1, 4, 256},  {&kTimer1, 5, 1024}, {&kTimer1, 6, 0},   {&kTimer1, 7, 0},
        {&kTimer2, 0, 0},    {&kTimer2, 1, 1},    {&kTimer2, 2, 8},    {&kTimer2, 3, 32},  {&kTimer2, 4, 64},
        {&kTimer2, 5, 128},  {&kTimer2, 6, 256},  {&kTimer2, 7, 1024},
    };
    for (const Case& c : cases) {
        Fixture f(*c.spec);
        f.unit.write_tccrb(0, c.cs);
        const std::string what = std::string("Timer") + c.spec->name + " CS=" + std::to_string(c.cs);
        if (c.n == 0) {
            EXPECT_EQ(f.unit.read_tcnt(100'000), 0) << what;
            continue;
        }
        EXPECT_EQ(f.unit.read_tcnt(3 * c.n - 1), 2) << what;
        EXPECT_EQ(f.unit.read_tcnt(3 * c.n), 3) << what;
        EXPECT_EQ(f.unit.read_tcnt(100 * c.n), 100) << what;
    }
}

// CTC on the seed 003 STEP pins (§5.2.5: STEP_X = OC0A, STEP_Y = OC2A): the datasheet's output frequency
// f_OCnA = f_clk / (2 N (1 + OCRnA)) (§15.7.2, §18.7.2), i.e. a toggle every N (1 + OCRnA) cycles. At 16 MHz
// (seed 003 §5.2.4): Timer2, N = 32, OCR2A = 124: a toggle every 4,000 cycles (2 kHz); Timer0, N = 64,
// OCR0A = 249: every 16,000 cycles (500 Hz). The first toggle comes (1 + OCR) ticks after the clock starts.
TEST(AvrTimerUnit, CtcToggleFrequencyIsFclkOver2NTimesOcrPlusOne) {
    struct Case {
        const TimerSpec* spec;
        std::uint8_t cs;
        int n;
        std::uint16_t ocr;
    };
    for (const Case& c : {Case{&kTimer2, 3, 32, 124}, Case{&kTimer0, 3, 64, 249}}) {
        Fixture f(*c.spec);
        f.unit.write_ocr(0, Channel::A, c.ocr);
        f.unit.write_tccra(0, 0x42);  // COMnA0 (toggle on match), WGMn1 (CTC, TOP = OCRnA)
        f.unit.write_tccrb(0, c.cs);
        const Cycle half_period = static_cast<Cycle>(c.n) * (1 + c.ocr);
        f.unit.advance_to(4 * half_period);
        const std::vector<Cycle> expected{half_period, 2 * half_period, 3 * half_period, 4 * half_period};
        EXPECT_EQ(toggle_cycles(f.rec.pins), expected) << "Timer" << c.spec->name;
        EXPECT_DOUBLE_EQ(16e6 / (2.0 * static_cast<double>(half_period)), c.spec->name == '2' ? 2000.0 : 500.0);
    }
}
