// The gtkwave save file beside a VCD (output/gtkw_save.hpp), against gtkwave 3.3's format: the flags are the bits
// of its src/analyzer.h (TraceEntFlagBits: BIN 3, RJUSTIFY 5, BLANK 9, ANALOG_STEP 15, ANALOG_INTERPOLATED 16,
// ANALOG_BLANK_STRETCH 17, GRP_BEGIN 23, GRP_END 24), times are in the timescale's unit, and zoom z shows 2^-z
// units per 200 px of the wave pane.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "output/gtkw_save.hpp"

namespace cnc::sim {
namespace {

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

std::string value_of(const std::vector<std::string>& lines, const std::string& key) {
    for (const std::string& l : lines) {
        if (l.rfind(key + " ", 0) == 0) return l.substr(key.size() + 1);
    }
    return "";
}

// The "*zoom marker A..Z" line.
std::vector<double> zoom_line(const std::vector<std::string>& lines) {
    for (const std::string& l : lines) {
        if (l.rfind('*', 0) != 0) continue;
        std::istringstream in(l.substr(1));
        std::vector<double> v;
        for (double x; in >> x;) v.push_back(x);
        return v;
    }
    return {};
}

TraceLayout square_layout(std::int64_t timescale_fs) {
    TraceLayout l;
    l.top_scope = "cncsim";
    l.signals = {{"link", "uart_rx"},
                 {"driver_x", "step_x"},
                 {"driver_x", "dir_x"},
                 {"carriage", "carriage_x_mm", true, false},
                 {"carriage", "carriage_y_mm", true, true}};
    l.timescale_fs = timescale_fs;
    l.from_ps = 0;
    l.to_ps = 50'000'000;
    return l;
}

// The wave pane the file asks for: 1400 px wide less the 240 px signal pane and 64 px of borders.
constexpr double kWavePx = 1400 - 240 - 64;

TEST(GtkwSave, PathBesideTheVcd) {
    EXPECT_EQ(gtkw_path("out/a.vcd"), "out/a.gtkw");
    EXPECT_EQ(gtkw_path("trace"), "trace.gtkw");
    EXPECT_EQ(gtkw_path("out/a.trace"), "out/a.trace.gtkw");
    EXPECT_EQ(gtkw_path("/dev/null"), std::nullopt);  // a device has no folder to put a file beside
}

TEST(GtkwSave, OneGroupPerBlockAndTheRealsAsAnalogTraces) {
    const std::vector<std::string> lines =
        lines_of(gtkw_text("/tmp/a.vcd", square_layout(100'000), TimeSpan{1'000'000, 3'000'000}));
    EXPECT_EQ(value_of(lines, "[dumpfile]"), "\"/tmp/a.vcd\"");
    std::vector<std::string> traces;
    for (auto it = std::find(lines.begin(), lines.end(), "[signals_width] 240"); it != lines.end(); ++it) {
        traces.push_back(*it);
    }
    const std::vector<std::string> expected = {"[signals_width] 240",
                                               "@800200",  // GRP_BEGIN | BLANK
                                               "-link",
                                               "@28",  // RJUSTIFY | BIN, a wire as gtkwave adds it
                                               "cncsim.link.uart_rx",
                                               "@1000200",  // GRP_END | BLANK
                                               "-link",
                                               "@800200",
                                               "-driver_x",
                                               "@28",
                                               "cncsim.driver_x.step_x",
                                               "@28",
                                               "cncsim.driver_x.dir_x",
                                               "@1000200",
                                               "-driver_x",
                                               "@800200",
                                               "-carriage",
                                               "@8028",  // ANALOG_STEP: ideal mechanics hold each position
                                               "cncsim.carriage.carriage_x_mm",
                                               "@20000",  // ANALOG_BLANK_STRETCH: four more rows of height
                                               "-",
                                               "-",
                                               "-",
                                               "-",
                                               "@10028",  // ANALOG_INTERPOLATED: samples of a moving carriage
                                               "cncsim.carriage.carriage_y_mm",
                                               "@20000",
                                               "-",
                                               "-",
                                               "-",
                                               "-",
                                               "@1000200",
                                               "-carriage"};
    EXPECT_EQ(traces, expected);
}

TEST(GtkwSave, ZoomedToTheFirstMoveWithTheMarkerOnItsFirstEdge) {
    // 100 ps timescale: gtkwave counts ps. The move runs 1 .. 3 us; a twentieth (0.1 us) either side.
    const std::vector<std::string> lines =
        lines_of(gtkw_text("/tmp/a.vcd", square_layout(100'000), TimeSpan{1'000'000, 3'000'000}));
    EXPECT_EQ(value_of(lines, "[timestart]"), "900000");
    const std::vector<double> z = zoom_line(lines);
    ASSERT_EQ(z.size(), 28U);  // zoom, the marker, the 26 named markers
    EXPECT_NEAR(std::pow(2.0, -z[0]) * kWavePx / 200.0, 2'200'000.0, 2'200'000.0 * 1e-5);
    EXPECT_EQ(z[1], 1'000'000.0);
    for (std::size_t i = 2; i < z.size(); ++i) EXPECT_EQ(z[i], -1.0);

    // 10 ns timescale: gtkwave counts ns.
    const std::vector<std::string> ns =
        lines_of(gtkw_text("/tmp/a.vcd", square_layout(10'000'000), TimeSpan{1'000'000, 3'000'000}));
    EXPECT_EQ(value_of(ns, "[timestart]"), "900");
    EXPECT_EQ(zoom_line(ns)[1], 1'000.0);
    EXPECT_NEAR(std::pow(2.0, -zoom_line(ns)[0]) * kWavePx / 200.0, 2'200.0, 2'200.0 * 1e-5);
}

TEST(GtkwSave, WholeFileWhenTheFirstMoveIsOutsideIt) {
    TraceLayout l = square_layout(100'000);
    l.from_ps = 10'000'000;  // a trace window that starts after the move
    const std::vector<std::string> lines = lines_of(gtkw_text("/tmp/a.vcd", l, TimeSpan{1'000'000, 3'000'000}));
    EXPECT_EQ(value_of(lines, "[timestart]"), "10000000");
    const std::vector<double> z = zoom_line(lines);
    EXPECT_NEAR(std::pow(2.0, -z[0]) * kWavePx / 200.0, 40'000'000.0, 40'000'000.0 * 1e-5);
    EXPECT_EQ(z[1], -1.0);  // no marker
    // No move at all (the lathe's tuning run): the whole file too.
    EXPECT_EQ(value_of(lines_of(gtkw_text("/tmp/a.vcd", square_layout(100'000), std::nullopt)), "[timestart]"), "0");
}

}  // namespace
}  // namespace cnc::sim
