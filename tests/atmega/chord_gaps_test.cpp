// ChordGapFold: the late chords of seed 003 §5.4.3 from the bytes' receive instants and the motion windows, fed as
// a run feeds them (a slice at a time, the bytes dropped once handed over) or all at the end.
#include <gtest/gtest.h>

#include <vector>

#include "architectures/atmega/chord_gaps.hpp"

using cnc::RecordLog;
using cnc::TimePs;
using cnc::sim::ChordGapFold;
using cnc::sim::ChordGaps;
using cnc::sim::MotionWindow;
namespace cad2g = cnc::host::cad2g;

namespace {

// A G01 (command 0), then an arc of three chords (command 1) and its terminator.
const std::vector<cad2g::Transfer> kTransfers{{0, 0, {}}, {1, 0, {}}, {1, 1, {}}, {1, 2, {}}, {1, -1, {}}};

// The windows as MotionWindowFold gives them (command, motion, begin, end, complete, Y steps before the begin and
// through the end). Chord 0 ends at 400 and chord 1 is reloaded at 405, Y stepping twice meanwhile (5 -> 7);
// chord 2 is reloaded at 500, where chord 1 ends.
const std::vector<MotionWindow> kWindows{{0, 0, 100, 200, true, 0, 0},
                                         {1, 0, 300, 400, true, 0, 5},
                                         {1, 1, 405, 500, true, 7, 9},
                                         {1, 2, 500, 600, true, 9, 12}};

struct Byte {
    std::size_t transfer;
    TimePs t_ps;
};
// Chord 1's last byte at 403, after chord 0 ended at 400: late. Chord 2's at 450, before chord 1 ended at 500.
const std::vector<Byte> kBytes{{0, 50}, {0, 60}, {1, 250}, {1, 280}, {2, 390}, {2, 403}, {3, 440}, {3, 450}, {4, 550}};

// The first n windows, as MotionWindowFold holds them.
RecordLog<MotionWindow> windows(std::size_t n = kWindows.size()) {
    RecordLog<MotionWindow> log;
    for (std::size_t i = 0; i < n; ++i) log.push_back(kWindows[i]);
    return log;
}

ChordGaps fed_at_the_end() {
    ChordGapFold fold(kTransfers);
    for (const Byte& b : kBytes) fold.add_byte(b.transfer, b.t_ps);
    fold.add_windows(windows(), true);
    return fold.gaps();
}

}  // namespace

// One late chord (chord 1): the wait from chord 0's end to chord 1's reload, 405 - 400 = 5, and the two Y steps
// taken in it, 7 - 5.
TEST(ChordGaps, ALateChordsWaitAndYStepsAreCounted) {
    const ChordGaps g = fed_at_the_end();
    EXPECT_EQ(g.late, 1);
    EXPECT_EQ(g.wait_max_ps, 5);
    EXPECT_EQ(g.y_steps_waiting, 2);
}

// A chord is judged only once a byte of a later transfer has come (its last byte is known then) or the run has
// ended; fed in any slices, the result is the whole run's.
TEST(ChordGaps, FedSliceBySliceEqualsTheWholeRun) {
    const ChordGaps whole = fed_at_the_end();
    for (std::size_t bytes_cut = 0; bytes_cut <= kBytes.size(); ++bytes_cut) {
        for (std::size_t windows_cut = 0; windows_cut <= kWindows.size(); ++windows_cut) {
            ChordGapFold fold(kTransfers);
            for (std::size_t i = 0; i < bytes_cut; ++i) fold.add_byte(kBytes[i].transfer, kBytes[i].t_ps);
            fold.add_windows(windows(windows_cut), false);
            for (std::size_t i = bytes_cut; i < kBytes.size(); ++i) fold.add_byte(kBytes[i].transfer, kBytes[i].t_ps);
            fold.add_windows(windows(), true);
            EXPECT_EQ(fold.gaps().late, whole.late) << bytes_cut << " " << windows_cut;
            EXPECT_EQ(fold.gaps().wait_max_ps, whole.wait_max_ps) << bytes_cut << " " << windows_cut;
            EXPECT_EQ(fold.gaps().y_steps_waiting, whole.y_steps_waiting) << bytes_cut << " " << windows_cut;
        }
    }
    ChordGapFold fold(kTransfers);
    for (std::size_t i = 0; i < 6; ++i) fold.add_byte(kBytes[i].transfer, kBytes[i].t_ps);  // up to chord 1's 403
    fold.add_windows(windows(), false);
    EXPECT_EQ(fold.next_window(), 2U);  // chord 1 waits: another of its bytes might still come
    EXPECT_EQ(fold.gaps().late, 0);
    fold.add_byte(3, 440);
    RecordLog<MotionWindow> read = windows();
    read.drop_before(2);  // the system drops the windows judged and handed to the metrics
    fold.add_windows(read, false);
    EXPECT_EQ(fold.next_window(), 3U);  // chord 2 waits for a byte of the terminator
    EXPECT_EQ(fold.gaps().late, 1);
}

// A chord none of whose bytes came (the run stopped before) has no receive instant to be late with.
TEST(ChordGaps, AChordWithNoBytesAtTheEndIsNotLate) {
    ChordGapFold fold(kTransfers);
    fold.add_windows(windows(), true);
    EXPECT_EQ(fold.gaps().late, 0);
    EXPECT_EQ(fold.next_window(), kWindows.size());
}
