// How long the seed 003 firmware is busy with motion before its next confirm (host/core/cad2g/firmware_busy.hpp),
// from the STEP period 2 N (OCR + 1) cycles at 16 MHz, N = 1024 (seed 003 eq. 2.3).
#include <gtest/gtest.h>

#include <sstream>

#include "host/core/cad2g/firmware_busy.hpp"
#include "host/core/gcode.hpp"

namespace cad2g = cnc::host::cad2g;

namespace {

cad2g::Plan plan(const std::string& text, cnc::host::FeedUnit unit = cnc::host::FeedUnit::MmPerMinute) {
    std::istringstream in(text);
    cnc::host::InterpreterOptions opt;
    opt.feed_unit = unit;
    return cad2g::plan_program(cnc::host::interpret(in, "t.nc", opt), cnc::host::MachineModel{}, {});
}

}  // namespace

// Thesis eqs. 5.1-5.2: 20 mm at 10.45 mm/s gets OCR 3: 3200 steps of 2 x 1024 x 4 = 8192 cycles, 1.6384 s, which
// is 20 mm at the OCR 3 speed of 12.207 mm/s.
TEST(Cad2gBusy, G01LastsItsXCountAtItsPeriod) {
    const cad2g::Plan p = plan("G1 X20 F10.45\n", cnc::host::FeedUnit::MmPerSecond);
    EXPECT_DOUBLE_EQ(cad2g::motion_s(p.commands.at(0).motions.at(0)), 3200.0 * 8192.0 / 16e6);
    EXPECT_NEAR(cad2g::motion_s(p.commands.at(0).motions.at(0)), 20.0 / 12.207, 1e-4);
}

// G00 at the rapid feed 1200 mm/min (OCR 1: 4096 cycles a step) runs both axes; the longer count decides,
// whichever axis it is on: 1600 steps x 4096 / 16 MHz = 0.4096 s.
TEST(Cad2gBusy, G00LastsItsLongerCount) {
    const cad2g::Plan x_longer = plan("G0 X-10 Y2.5\n");
    const cad2g::Plan y_longer = plan("G0 X2.5 Y-10\n");
    EXPECT_DOUBLE_EQ(cad2g::motion_s(x_longer.commands.at(0).motions.at(0)), 1600.0 * 4096.0 / 16e6);
    EXPECT_DOUBLE_EQ(cad2g::motion_s(y_longer.commands.at(0).motions.at(0)), 1600.0 * 4096.0 / 16e6);
}

// Per transfer: a G00 or G01 its own motion, an arc's first chord nothing, chord k the chord before it, the
// terminator the last chord, M30 nothing. G1 X25 from X20 at F600: 800 steps at OCR 3 (3.88 truncated), 0.4096 s.
TEST(Cad2gBusy, PerTransferTheMotionBeforeTheNextConfirm) {
    const cad2g::Plan p = plan("G0 X20 Y10\nG1 X25 F600\nG3 X15 Y10 I-5 J0 F600\n");
    const std::vector<cad2g::Transfer> t = cad2g::transfers(p);
    const std::vector<double> busy = cad2g::motion_before_next_confirm_s(p, t);
    ASSERT_EQ(busy.size(), t.size());
    const std::vector<cad2g::Motion>& chords = p.commands.at(2).motions;
    ASSERT_EQ(t.size(), 2U + chords.size() + 2U);  // G00, G01, the chords, the terminator, M30
    EXPECT_DOUBLE_EQ(busy[0], cad2g::motion_s(p.commands.at(0).motions.at(0)));
    EXPECT_DOUBLE_EQ(busy[1], 800.0 * 8192.0 / 16e6);
    EXPECT_EQ(busy[2], 0.0);
    for (std::size_t k = 1; k < chords.size(); ++k) EXPECT_DOUBLE_EQ(busy[2 + k], cad2g::motion_s(chords[k - 1])) << k;
    EXPECT_DOUBLE_EQ(busy[2 + chords.size()], cad2g::motion_s(chords.back()));
    EXPECT_EQ(busy.back(), 0.0);
}
