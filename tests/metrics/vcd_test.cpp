#include <gtest/gtest.h>

#include <sstream>

#include "common/bad_input.hpp"
#include "metrics/vcd/vcd_reader.hpp"
#include "metrics/vcd/vcd_timescale.hpp"
#include "metrics/vcd/vcd_writer.hpp"

namespace cnc::metrics {
namespace {

std::map<std::string, EdgeLog> read(const std::string& text) {
    std::istringstream in(text);
    return read_vcd(in, "t.vcd").signals;
}

// Message of the BadInput that reading `text` throws ("" if it does not throw).
std::string error_of(const std::string& text) {
    try {
        (void)read(text);
    } catch (const BadInput& e) {
        return e.what();
    }
    return "";
}

// What SystemC 2.3.4's sc_trace VCD writer produces (copied from a real trace of a bool, a nested
// bool and an int signal).
const char* const kSystemCVcd = R"($date
     Nov 21, 2026       09:08:02
$end

$version
 SystemC 2.3.4-Accellera --- Jan 13 2023 17:28:48
$end

$timescale
     1 ps
$end

$scope module SystemC $end
$var wire    1  aaaaa  step_x       $end
$var wire   32  aaaac  cnt [31:0]  $end
$scope module top $end
$var wire    1  aaaab  dir_x       $end
$upscope $end
$upscope $end
$enddefinitions  $end

$comment
All initial values are dumped below at time 0 sec = 0 timescale units.
$end

$dumpvars
0aaaaa
0aaaab
b0 aaaac
$end

#1000
1aaaab

#651000
1aaaaa

#2651000
0aaaaa

#5301000
1aaaaa
b1 aaaac

#7301000
0aaaaa

#20000000
)";

TEST(MetricsVcdRead, SystemCTrace) {
    std::istringstream in(kSystemCVcd);
    const VcdContents vcd = read_vcd(in, "t.vcd");
    EXPECT_EQ(vcd.other_variables.at("cnt"), "32 bits wide (wire)");  // not read, but known by leaf and path
    EXPECT_EQ(vcd.other_variables.at("SystemC.cnt"), "32 bits wide (wire)");
    const auto& logs = vcd.signals;
    ASSERT_EQ(logs.size(), 2U);
    const EdgeLog& step = logs.at("step_x");
    EXPECT_EQ(step.name, "step_x");
    EXPECT_FALSE(step.initial);
    EXPECT_EQ(step.rising(), (std::vector<TimePs>{651'000, 5'301'000}));
    EXPECT_EQ(step.falling(), (std::vector<TimePs>{2'651'000, 7'301'000}));
    const EdgeLog& dir = logs.at("dir_x");
    EXPECT_FALSE(dir.initial);
    ASSERT_EQ(dir.edges.size(), 1U);
    EXPECT_EQ(dir.edges[0].t_ps, 1'000);
    EXPECT_TRUE(dir.edges[0].level);
}

std::string with_timescale(const std::string& ts) {
    return "$timescale " + ts + " $end\n$var wire 1 ! s $end\n$enddefinitions $end\n#0\n0!\n#3\n1!\n";
}

TEST(MetricsVcdRead, TimescalesConvertToExactPicoseconds) {
    const std::vector<std::pair<std::string, TimePs>> cases{{"1 ps", 3},
                                                            {"10ps", 30},
                                                            {"100 ps", 300},
                                                            {"1 ns", 3'000},
                                                            {"10 ns", 30'000},
                                                            {"100ns", 300'000},
                                                            {"1 us", 3'000'000},
                                                            {"10 us", 30'000'000},
                                                            {"100 us", 300'000'000},
                                                            {"1 ms", 3'000'000'000},
                                                            {"100 ms", 300'000'000'000},
                                                            {"1 s", 3'000'000'000'000},
                                                            {"10 s", 30'000'000'000'000},
                                                            {"100 s", 300'000'000'000'000}};
    for (const auto& [ts, t_ps] : cases) {
        const auto logs = read(with_timescale(ts));
        EXPECT_EQ(logs.at("s").rising(), std::vector<TimePs>{t_ps}) << ts;
    }
    // Split over lines as SystemC writes it.
    EXPECT_EQ(read(with_timescale("\n  10\n  ns\n")).at("s").rising(), std::vector<TimePs>{30'000});
}

TEST(MetricsVcdRead, DuplicateLeafNamesGetTheirScopePath) {
    // Scope "b" is declared without a type, as some hand-written generators do.
    const auto logs = read(
        "$timescale 1ns $end\n"
        "$scope module top $end\n$scope module a $end\n$var wire 1 ! step $end\n$upscope $end\n"
        "$scope b $end\n$var reg 1 \" step $end\n$upscope $end\n$var wire 1 # dir $end\n$upscope $end\n"
        "$enddefinitions $end\n");
    ASSERT_EQ(logs.size(), 3U);
    EXPECT_EQ(logs.count("top.a.step"), 1U);
    EXPECT_EQ(logs.count("top.b.step"), 1U);
    EXPECT_EQ(logs.count("dir"), 1U);
    EXPECT_EQ(logs.at("top.b.step").name, "top.b.step");
}

TEST(MetricsVcdRead, LogicAnalyserStyleWithoutDumpvars) {
    // First values at the first timestamp are the initial levels; x and z read as 0; a 1-bit variable in
    // vector form, bit-selects of a bus, reals and $dumpoff sections.
    const auto logs = read(
        "$timescale 1 us $end\n$var wire 1 ! D0 $end\n$var wire 1 \" D1 $end\n$var wire 1 # bus [3] $end\n"
        "$var real 64 $ r $end\n$enddefinitions $end\n"
        "#5 1! 0\" 1#\n#7 0! x\" r1.5 $\n#9 b1 \" z#\n#10 $dumpoff x! x\" $end\n#11 $dumpon 1! 1\" $end\n");
    const EdgeLog& d0 = logs.at("D0");
    EXPECT_TRUE(d0.initial);
    EXPECT_EQ(d0.falling(), std::vector<TimePs>{7'000'000});
    EXPECT_EQ(d0.rising(), std::vector<TimePs>{11'000'000});  // $dumpoff's x did not count
    const EdgeLog& d1 = logs.at("D1");
    EXPECT_FALSE(d1.initial);
    EXPECT_EQ(d1.rising(), (std::vector<TimePs>{9'000'000}));
    EXPECT_EQ(d1.edges.size(), 1U);  // x at 7 us is 0 (no change); 1 again at 11 us is no change
    EXPECT_EQ(logs.at("bus[3]").falling(), std::vector<TimePs>{9'000'000});
    EXPECT_EQ(logs.count("r"), 0U);
}

TEST(MetricsVcdRead, DumpvarsSetsInitialLevelsAndLaterChangesAtTimeZeroAreEdges) {
    const auto logs = read(
        "$timescale 1 ns $end\n$var wire 1 ! s $end\n$enddefinitions $end\n"
        "#0\n$dumpvars\n1!\n$end\n0!\n#4\n1!\n");
    const EdgeLog& s = logs.at("s");
    EXPECT_TRUE(s.initial);
    EXPECT_EQ(s.falling(), std::vector<TimePs>{0});
    EXPECT_EQ(s.rising(), std::vector<TimePs>{4'000});
}

TEST(MetricsVcdRead, VariableFirstSeenLaterStartsLow) {
    const auto logs = read(
        "$timescale 1 ns $end\n$var wire 1 ! s $end\n$var wire 1 \" t $end\n"
        "$enddefinitions $end\n#0\n0\"\n#5\n1!\n");
    EXPECT_FALSE(logs.at("s").initial);
    EXPECT_EQ(logs.at("s").rising(), std::vector<TimePs>{5'000});
}

const char* const kHead = "$timescale 1 ns $end\n$var wire 1 ! s $end\n$enddefinitions $end\n";

TEST(MetricsVcdRead, MalformedInputNamesFileAndLine) {
    const std::vector<std::pair<std::string, std::string>> cases{
        {"$var wire 1 ! s $end\n$enddefinitions $end\n", "t.vcd:2: no $timescale"},
        {"$timescale 3 ns $end\n", "t.vcd:1: $timescale '3ns' is not"},
        {"$timescale 1000 fs $end\n", "t.vcd:1: $timescale '1000fs' is not"},
        {"$timescale ns $end\n", "t.vcd:1: $timescale 'ns' is not"},
        {"$timescale 1 ns $end\n$var wire 1 ! s\n", "t.vcd:2: $var is not closed by $end"},
        {"$timescale 1 ns $end\n$var wire 1 ! $end\n", "t.vcd:2: $var needs"},
        {"$timescale 1 ns $end\n$var wire one ! s $end\n", "t.vcd:2: $var size 'one' is not a number"},
        {"$timescale 1 ns $end\n$scope $end\n", "t.vcd:2: $scope needs"},
        {"$timescale 1 ns $end\n$scope module top extra $end\n", "t.vcd:2: $scope needs"},
        {"$timescale 1 ns $end\n$upscope $end\n", "t.vcd:2: $upscope without"},
        {"$timescale 1 ns $end\n$var wire 1 ! s $end\n", "t.vcd:2: the header has no $enddefinitions"},
        {"$timescale 1 ns $end\n1!\n", "t.vcd:2: unexpected '1!' in the header"},
        {"$comment never closed\n", "t.vcd:1: $comment is not closed"},
        {std::string(kHead) + "#12a\n", "t.vcd:4: time '#12a' is not a whole number"},
        {std::string(kHead) + "#\n", "t.vcd:4: time '#' is not"},
        {std::string(kHead) + "#10\n#9\n", "t.vcd:5: time goes backwards"},
        {std::string(kHead) + "#99999999999999999999\n", "t.vcd:4: time '#99999999999999999999' is too large"},
        {std::string(kHead) + "#9999999999999999\n", "t.vcd:4: time '#9999999999999999' is too large in ps"},
        {std::string(kHead) + "1?\n", "t.vcd:4: value change for undeclared identifier '?'"},
        {std::string(kHead) + "1\n", "t.vcd:4: value change '1' has no identifier"},
        {std::string(kHead) + "b12 !\n", "t.vcd:4: vector value 'b12' is not binary"},
        {std::string(kHead) + "b1\n", "t.vcd:4: value 'b1' has no identifier"},
        {std::string(kHead) + "b1 ?\n", "t.vcd:4: value change for undeclared identifier '?'"},
        {std::string(kHead) + "$end\n", "t.vcd:4: $end without an open"},
        {std::string(kHead) + "$dumpvars\n$dumpvars\n", "t.vcd:5: $dumpvars inside an open $dumpvars"},
        {std::string(kHead) + "$dumpvars\n0!\n", "t.vcd:4: $dumpvars is not closed by $end"},
        {std::string(kHead) + "$var wire 1 # t $end\n", "t.vcd:4: unexpected '$var' after $enddefinitions"},
        {std::string(kHead) + "?!\n", "t.vcd:4: unexpected '?!'"},
        {"$timescale 1 ns $end\n$var wire 1 ! s $end\n$var wire 1 \" s $end\n$enddefinitions $end\n",
         "t.vcd:3: signal 's' is declared twice"},
    };
    for (const auto& [text, expected] : cases) {
        const std::string msg = error_of(text);
        EXPECT_EQ(msg.substr(0, expected.size()), expected) << "input:\n" << text << "message: " << msg;
    }
}

TEST(MetricsVcdWrite, RoundTripAtNanosecondTimescale) {
    EdgeLog step{"step_x", false, {}};
    step.add(0, true);  // an edge at time 0 stays an edge, not the initial level
    step.add(2'000'000, false);
    step.add(312'500'000, true);
    step.add(314'500'000, false);
    EdgeLog dir{"dir_x", true, {}};
    dir.add(312'000'000, false);
    std::ostringstream out;
    write_vcd(out, {step, dir});
    EXPECT_NE(out.str().find("$timescale 1 ns $end"), std::string::npos);
    const auto logs = read(out.str());
    ASSERT_EQ(logs.size(), 2U);
    const EdgeLog& s = logs.at("step_x");
    EXPECT_FALSE(s.initial);
    ASSERT_EQ(s.edges.size(), step.edges.size());
    for (std::size_t i = 0; i < s.edges.size(); ++i) {
        EXPECT_EQ(s.edges[i].t_ps, step.edges[i].t_ps);
        EXPECT_EQ(s.edges[i].level, step.edges[i].level);
    }
    EXPECT_TRUE(logs.at("dir_x").initial);
    EXPECT_EQ(logs.at("dir_x").falling(), std::vector<TimePs>{312'000'000});
}

TEST(MetricsVcdWrite, PicosecondTimescaleAndManySignals) {
    // More signals than one-character identifiers: two-character ids must round-trip too.
    std::vector<EdgeLog> logs;
    for (int i = 0; i < 100; ++i) {
        EdgeLog l{"s" + std::to_string(i), false, {}};
        l.add(1 + i, true);
        logs.push_back(l);
    }
    std::ostringstream out;
    write_vcd(out, logs, 1'000);
    const auto back = read(out.str());
    ASSERT_EQ(back.size(), 100U);
    EXPECT_EQ(back.at("s99").rising(), std::vector<TimePs>{100});
}

TEST(MetricsVcdWrite, RejectsBadTimescaleTimesAndNames) {
    const auto error = [](const std::vector<EdgeLog>& logs, std::int64_t ts_fs) -> std::string {
        std::ostringstream out;
        try {
            write_vcd(out, logs, ts_fs);
        } catch (const BadInput& e) {
            return e.what();
        }
        return "";
    };
    EdgeLog ok{"s", false, {{1'000, true}}};
    EdgeLog off_grid{"s", false, {{1'500, true}}};
    constexpr std::int64_t k1ns = 1'000'000;
    EXPECT_EQ(error({ok}, 3'000'000).rfind("write_vcd: timescale 3000000 fs is not", 0), 0U);
    EXPECT_EQ(error({off_grid}, k1ns)
                  .rfind("write_vcd: signal 's': edge at 1500 ps is not a multiple of the "
                         "timescale (1 ns)",
                         0),
              0U);
    EXPECT_EQ(error({EdgeLog{"a b", false, {}}}, k1ns).rfind("write_vcd: signal name 'a b'", 0), 0U);
    EXPECT_EQ(error({ok, ok}, k1ns).rfind("write_vcd: signal 's' given twice", 0), 0U);
    EXPECT_EQ(error({EdgeLog{"s", false, {{5'000, true}, {4'000, false}}}}, k1ns)
                  .rfind("write_vcd: signal 's': edge at 4000 ps is negative or out of time order", 0),
              0U);
    EXPECT_EQ(error({ok}, k1ns), "");
}

TEST(MetricsVcdTimescale, EveryStandardValueFromSecondsToFemtoseconds) {
    const std::vector<std::string> names = vcd_timescale_names();
    ASSERT_EQ(names.size(), 18U);
    EXPECT_EQ(names.front(), "100 s");
    EXPECT_EQ(names.back(), "1 fs");
    for (const std::string& n : names) EXPECT_EQ(format_vcd_timescale(*parse_vcd_timescale_fs(n)), n);
    EXPECT_EQ(parse_vcd_timescale_fs("100ps"), 100'000);
    EXPECT_EQ(parse_vcd_timescale_fs("10 fs"), 10);
    EXPECT_EQ(parse_vcd_timescale_fs("1 s"), 1'000'000'000'000'000);
    for (const char* bad : {"1000 fs", "5 ns", "1 min", "ns", "", "1 ps 2"}) {
        EXPECT_EQ(parse_vcd_timescale_fs(bad), std::nullopt) << bad;
    }
    EXPECT_EQ(format_vcd_timescale(500'000), std::nullopt);
}

TEST(MetricsVcdTimescale, TicksToAndFromPicoseconds) {
    EXPECT_EQ(vcd_ticks_to_ps(7, 100'000), 700);  // 100 ps
    EXPECT_EQ(vcd_ticks_to_ps(4, 100), 0);        // 400 fs: nearest ps
    EXPECT_EQ(vcd_ticks_to_ps(5, 100), 1);        // 500 fs: half up
    EXPECT_EQ(vcd_ticks_to_ps(15, 100), 2);
    EXPECT_EQ(vcd_ticks_to_ps(9'000'000'000'000'000'000, 1'000'000), std::nullopt);  // past int64 in ps
    EXPECT_EQ(ps_to_vcd_ticks(8'666'667, 100'000), 86'667);                          // nearest 100 ps tick
    EXPECT_EQ(ps_to_vcd_ticks(8'666'649, 100'000), 86'666);
    EXPECT_EQ(ps_to_vcd_ticks(3, 10), 300);  // 10 fs ticks
    EXPECT_THROW((void)ps_to_vcd_ticks(10'000'000'000'000'000, 1), std::overflow_error);
    EXPECT_TRUE(on_vcd_tick(62'500, 100'000));
    EXPECT_FALSE(on_vcd_tick(62'500, 1'000'000));
    EXPECT_TRUE(on_vcd_tick(1, 100));
}

TEST(MetricsVcdRead, FemtosecondTimesRoundToTheNearestPicosecond) {
    const auto logs = read(
        "$timescale 100 fs $end\n$var wire 1 ! s $end\n$enddefinitions $end\n"
        "#0\n0!\n#4\n1!\n#5\n0!\n#15\n1!\n");
    EXPECT_EQ(logs.at("s").rising(), (std::vector<TimePs>{0, 2}));
    EXPECT_EQ(logs.at("s").falling(), (std::vector<TimePs>{1}));
}

// What sigrok-cli 0.7.2 (libsigrok 0.5.2) writes for `-O vcd`: a META line before $date, a $comment before
// $enddefinitions, '$' and '"' as identifiers, every change of an instant on the timestamp's line, and a last
// timestamp without changes (copied from an export of out/square.vcd at 1 GHz).
const char* const kSigrokExport = R"(META samplerate: 1000000000
$date Mon Nov 23 22:36:14 2026 $end
$version libsigrok 0.5.2 $end
$comment
  Acquisition with 4/4 channels at 1 GHz
$end
$timescale 1 ns $end
$scope module libsigrok $end
$var wire 1 ! step_x $end
$var wire 1 " dir_x $end
$var wire 1 # step_y $end
$var wire 1 $ dir_y $end
$upscope $end
$enddefinitions $end
#0 0! 0" 0# 1$
#351949240 1"
#351953260 1! 1#
#351955260 0! 0#
#454000000
)";

TEST(MetricsVcdRead, SigrokCliExport) {
    const auto logs = read(kSigrokExport);
    ASSERT_EQ(logs.size(), 4U);
    EXPECT_TRUE(logs.at("dir_y").initial);
    EXPECT_EQ(logs.at("dir_y").edges.size(), 0U);
    EXPECT_EQ(logs.at("dir_x").rising(), std::vector<TimePs>{351'949'240'000});
    EXPECT_EQ(logs.at("step_x").rising(), std::vector<TimePs>{351'953'260'000});
    EXPECT_EQ(logs.at("step_y").falling(), std::vector<TimePs>{351'955'260'000});
}

// The streaming writer, as the run uses it: exact edges of clocked signals, the others at the nearest tick.
TEST(MetricsVcdWrite, StreamingWriterRoundsOnlyUnclockedSignals) {
    std::ostringstream out;
    VcdWriter w(out, 100'000, {{"step_x", false, 50'000'000}, {"uart_rx", true, std::nullopt}}, "test");
    w.change(20'000, 0, true);
    w.change(8'660'000, 0, false);
    w.change(8'666'667, 1, false);  // a CP2102 edge: 86 666.67 ticks -> 86 667
    w.finish(9'000'000);
    const std::string text = out.str();
    EXPECT_EQ(text.find("$comment"), std::string::npos);
    EXPECT_NE(text.find("$timescale 100 ps $end"), std::string::npos);
    EXPECT_NE(text.find("#0\n$dumpvars\n0!\n1\"\n$end\n#200\n1!\n#86600\n0!\n#86667\n0\"\n#90000\n"), std::string::npos)
        << text;
    const auto logs = read(text);
    EXPECT_EQ(logs.at("uart_rx").falling(), std::vector<TimePs>{8'666'700});
    EXPECT_THROW(w.change(8'000'000, 0, true), std::logic_error);  // back in time
    EXPECT_THROW(w.change(9'010'000, 0, true), std::logic_error);  // not on the 20 ns clock
}

// Real variables as IEEE 1364 §18.2 has them (what gtkwave reads): "$var real 64", values "r<%.16g> <id>"
// (0.1 + 0.2 is 0.30000000000000004, whose 16 significant digits are 0.3). The reader keeps them out of the
// 1-bit signals.
TEST(MetricsVcdWrite, RealVariablesBesideWires) {
    std::ostringstream out;
    VcdWriter w(out, 1'000,
                {{"step_x", false, std::nullopt}, {"carriage_x_mm", false, std::nullopt, VcdVarKind::Real, 12.5}},
                "test");
    w.change(1'000, 0, true);
    w.change_real(1'000, 1, 12.50625);
    w.change_real(3'000, 1, 0.1 + 0.2);
    w.change_real(4'000, 1, -1e-7);
    w.finish(5'000);
    const std::string text = out.str();
    EXPECT_NE(text.find("$var wire 1 ! step_x $end\n$var real 64 \" carriage_x_mm $end\n"), std::string::npos);
    EXPECT_NE(text.find("$dumpvars\n0!\nr12.5 \"\n$end\n#1000\n1!\nr12.50625 \"\n#3000\nr0.3 \"\n"
                        "#4000\nr-1e-07 \"\n#5000\n"),
              std::string::npos)
        << text;
    std::istringstream in(text);
    const VcdContents read_back = read_vcd(in, "t.vcd");
    EXPECT_EQ(read_back.signals.count("carriage_x_mm"), 0U);
    EXPECT_EQ(read_back.other_variables.at("carriage_x_mm"), "64 bits wide (real)");
    EXPECT_THROW(w.change(5'000, 1, true), std::logic_error);      // a real is not a wire
    EXPECT_THROW(w.change_real(5'000, 0, 1.0), std::logic_error);  // nor a wire a real
}

TEST(MetricsVcdWrite, RefusesATimescaleThatWouldRoundAClockedEdge) {
    const std::vector<VcdSignal> pins{
        {"step_x", false, 16'000'000}, {"uart_tx", false, 50'000'000}, {"uart_rx", true, 24'000'000}};
    EXPECT_NO_THROW(check_vcd_signals(100'000, pins, "s.toml: trace.timescale"));
    EXPECT_NO_THROW(check_vcd_signals(1, pins, "s.toml: trace.timescale"));
    try {
        check_vcd_signals(1'000'000, pins, "s.toml: trace.timescale");
        FAIL() << "1 ns accepted for a 62.5 ns clock";
    } catch (const BadInput& e) {
        EXPECT_STREQ(e.what(),
                     "s.toml: trace.timescale: 1 ns would round the edges of step_x (its clock, 16000000 "
                     "Hz, has a period of 62500 ps); the coarsest timescale that keeps every clocked edge "
                     "exact is 100 ps");
    }
    // The CP2102's 24 MHz has no whole-ps period: its edges are rounded, whatever the timescale.
    EXPECT_NO_THROW(check_vcd_signals(10'000'000, {{"uart_rx", true, 24'000'000}}, "t"));
    EXPECT_EQ(whole_period_ps(24'000'000), std::nullopt);
    EXPECT_EQ(whole_period_ps(50'000'000), 20'000);
}

}  // namespace
}  // namespace cnc::metrics
