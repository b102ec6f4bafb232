// The atmega system's readings of the pins: STEP pulses the driver takes (EN low), and the windows of the
// commands and chords from the PORTB pins.
#include <gtest/gtest.h>

#include <algorithm>

#include "systems/atmega/motion_windows.hpp"

namespace s3 = cnc::host::seed003;
using cnc::EdgeLog;
using cnc::sim::MotionWindow;

namespace {

EdgeLog log(const char* name, bool initial, std::vector<cnc::Edge> edges) { return EdgeLog{name, initial, edges}; }

s3::Plan g01_then_arc_of_three() {
    s3::Plan p;
    p.commands.push_back({s3::CommandId::G01, {s3::Motion{}}});
    p.commands.push_back({s3::CommandId::G03, {s3::Motion{}, s3::Motion{}, s3::Motion{}}});
    p.commands.push_back({s3::CommandId::M30, {}});
    return p;
}

struct Pins {
    EdgeLog en_x, en_y, dir_x, dir_y, head;
};

// G01 at 100..200; arc: chord 0 from 300, its ISR end at 400; chord 1 (dx = 0: DIR_X flips, EN_X stays high)
// reloaded at 405; chord 2 reloaded at 500 (EN_X falls, DIR_X back), its ISR end at 600; the terminator
// raises EN_Y at 650; M30 turns the head off at 700.
Pins arc_pins() {
    return {log("n_enbl_x", true, {{100, false}, {200, true}, {300, false}, {400, true}, {500, false}, {600, true}}),
            log("n_enbl_y", true, {{100, false}, {200, true}, {300, false}, {650, true}}),
            log("dir_x", false, {{405, true}, {500, false}}),
            log("dir_y", false, {}),
            log("laser", false, {{100, true}, {700, false}})};
}

void expect_window(const MotionWindow& w, std::size_t command, std::size_t motion, cnc::TimePs begin,
                   cnc::TimePs end, bool complete = true) {
    EXPECT_EQ(w.command, command);
    EXPECT_EQ(w.motion, motion);
    EXPECT_EQ(w.t_begin_ps, begin);
    EXPECT_EQ(w.t_end_ps, end);
    EXPECT_EQ(w.complete, complete);
}

}  // namespace

TEST(MotionWindows, CommandsAndChordsFromThePortbPins) {
    const Pins p = arc_pins();
    const auto w = cnc::sim::motion_windows(g01_then_arc_of_three(), {p.en_x, p.en_y, p.dir_x, p.dir_y, p.head}, 1000);
    ASSERT_EQ(w.size(), 4U);
    expect_window(w[0], 0, 0, 100, 200);
    expect_window(w[1], 1, 0, 300, 400);  // ends at its ISR (EN_X alone)
    expect_window(w[2], 1, 1, 405, 500);  // X disabled: ends where the next chord starts
    expect_window(w[3], 1, 2, 500, 600);
}

TEST(MotionWindows, ARunThatStopsEarlyClosesTheOpenMotion) {
    Pins p = arc_pins();
    for (EdgeLog* l : {&p.en_x, &p.en_y, &p.dir_x, &p.dir_y, &p.head}) {
        const auto late = [](const cnc::Edge& e) { return e.t_ps > 450; };
        l->edges.erase(std::remove_if(l->edges.begin(), l->edges.end(), late), l->edges.end());
    }
    const auto w = cnc::sim::motion_windows(g01_then_arc_of_three(), {p.en_x, p.en_y, p.dir_x, p.dir_y, p.head}, 450);
    ASSERT_EQ(w.size(), 3U);
    expect_window(w[2], 1, 1, 405, 450, false);
}
