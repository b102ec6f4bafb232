// The atmega system's readings of the pins: STEP pulses the driver takes (EN low), and the windows of the
// commands and chords from the PORTB pins.
#include <gtest/gtest.h>

#include <algorithm>

#include "architectures/atmega/motion_windows.hpp"

namespace cad2g = cnc::host::cad2g;
using cnc::EdgeLog;
using cnc::sim::MotionWindow;

namespace {

EdgeLog log(const char* name, bool initial, std::vector<cnc::Edge> edges) {
    return EdgeLog{name, initial, edges};
}

cad2g::Plan g01_then_arc_of_three() {
    cad2g::Plan p;
    p.commands.push_back({cad2g::CommandId::G01, {cad2g::Motion{}}});
    p.commands.push_back({cad2g::CommandId::G03, {cad2g::Motion{}, cad2g::Motion{}, cad2g::Motion{}}});
    p.commands.push_back({cad2g::CommandId::M30, {}});
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
            log("dir_x", false, {{405, true}, {500, false}}), log("dir_y", false, {}),
            log("laser", false, {{100, true}, {700, false}})};
}

void expect_window(const MotionWindow& w, std::size_t command, std::size_t motion, cnc::TimePs begin, cnc::TimePs end,
                   bool complete = true) {
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

namespace {

bool same_windows(const std::vector<MotionWindow>& a, const std::vector<MotionWindow>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (a[i].command != b[i].command || a[i].motion != b[i].motion || a[i].t_begin_ps != b[i].t_begin_ps ||
            a[i].t_end_ps != b[i].t_end_ps || a[i].complete != b[i].complete ||
            a[i].y_steps_before_begin != b[i].y_steps_before_begin ||
            a[i].y_steps_through_end != b[i].y_steps_through_end) {
            return false;
        }
    }
    return true;
}

// Y pulses of arc_pins(): one inside chord 0 (350), two between its ISR end at 400 and the reload at 405 (late
// data: 401, 403), one on the reload's instant (405, before it: not in the gap), one in chord 1 (450).
EdgeLog y_pulses() {
    return log("step_y", false,
               {{350, true},
                {351, false},
                {401, true},
                {402, false},
                {403, true},
                {404, false},
                {405, true},
                {406, false},
                {450, true},
                {451, false}});
}

// The fold fed the pins cut at `cuts` (each slice's logs as EdgeRecorder::take_before hands them over).
std::vector<MotionWindow> fold_in_slices(const cad2g::Plan& plan, Pins p, EdgeLog y,
                                         const std::vector<cnc::TimePs>& cuts, cnc::TimePs t_end) {
    cnc::sim::MotionWindowFold fold(plan);
    for (const cnc::TimePs cut : cuts) {
        const EdgeLog en_x = p.en_x.take_before(cut), en_y = p.en_y.take_before(cut);
        const EdgeLog dir_x = p.dir_x.take_before(cut), dir_y = p.dir_y.take_before(cut);
        const EdgeLog head = p.head.take_before(cut);
        fold.add({en_x, en_y, dir_x, dir_y, head}, y.take_before(cut));
    }
    fold.finish(t_end);
    return {fold.windows().begin(), fold.windows().end()};
}

}  // namespace

// The windows found as the pins change: cut before, at and after every closing change (the ISR end, the reload,
// both EN high), each window is the whole run's, and a window is there as soon as its closing change is read.
TEST(MotionWindows, FedSliceBySliceEqualsTheWholeRun) {
    const Pins p = arc_pins();
    const std::vector<MotionWindow> whole = fold_in_slices(g01_then_arc_of_three(), p, y_pulses(), {2000}, 2000);
    ASSERT_EQ(whole.size(), 4U);
    for (const cnc::TimePs t : {100, 200, 300, 400, 401, 405, 406, 500, 600, 650, 700}) {
        for (const std::vector<cnc::TimePs>& cuts :
             {std::vector<cnc::TimePs>{t, 2000}, {t - 1, t, t + 1, 2000}, {50, 150, t, 2000}}) {
            EXPECT_TRUE(same_windows(fold_in_slices(g01_then_arc_of_three(), p, y_pulses(), cuts, 2000), whole))
                << "cut at " << t;
        }
    }
    const cad2g::Plan plan = g01_then_arc_of_three();
    cnc::sim::MotionWindowFold fold(plan);
    Pins q = arc_pins();
    const auto read_before = [&](cnc::TimePs cut) {
        const EdgeLog en_x = q.en_x.take_before(cut), en_y = q.en_y.take_before(cut);
        const EdgeLog dir_x = q.dir_x.take_before(cut), dir_y = q.dir_y.take_before(cut);
        fold.add({en_x, en_y, dir_x, dir_y, q.head.take_before(cut)}, EdgeLog{});
    };
    read_before(400);
    EXPECT_EQ(fold.windows().size(), 1U);  // the G01; chord 0's ISR end not read yet
    read_before(405);
    EXPECT_EQ(fold.windows().size(), 1U);  // the ISR end read, the reload not: chord 0 may still end elsewhere
    read_before(406);
    EXPECT_EQ(fold.windows().size(), 2U);
}

// chord_gaps' Y steps between chord 0's end (400) and chord 1's reload (405): the pulses at 401 and 403, not the one
// at 350 (in the chord) nor at 405 (the reload's own instant).
TEST(MotionWindows, YStepsBetweenAChordsEndAndTheReloadAreCounted) {
    const std::vector<MotionWindow> w = fold_in_slices(g01_then_arc_of_three(), arc_pins(), y_pulses(), {2000}, 2000);
    ASSERT_EQ(w.size(), 4U);
    EXPECT_EQ(w[1].y_steps_through_end, 1);   // 350
    EXPECT_EQ(w[2].y_steps_before_begin, 3);  // 350, 401, 403
    EXPECT_EQ(w[2].y_steps_before_begin - w[1].y_steps_through_end, 2);
}
