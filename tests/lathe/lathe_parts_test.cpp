// The plant's small parts against their datasheets' truth tables and seed 002's wiring (§2.3, §2.5.3).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "lathe/core/keypad.hpp"
#include "lathe/core/l298.hpp"
#include "lathe/core/slotted_encoder.hpp"

namespace {

using cnc::lathe::BridgeMode;
using cnc::lathe::KeypadMatrix;
using cnc::lathe::L298;
using cnc::lathe::SlottedEncoder;

// L298 datasheet, bidirectional motor control table: Ven = H, C != D turns the motor (C = H forward), C = D is a
// fast motor stop; Ven = L is a free running motor stop whatever C and D. 24 V less 2 V of drop (seed 002 §2.3).
TEST(L298, TruthTable) {
    L298 b;
    for (const bool in1 : {false, true}) {
        for (const bool in2 : {false, true}) {
            b.in1 = in1;
            b.in2 = in2;
            b.en_a = false;
            EXPECT_EQ(b.mode(), BridgeMode::Coast);
            b.en_a = true;
            EXPECT_EQ(b.mode(), in1 != in2 ? BridgeMode::Drive : BridgeMode::Brake);
        }
    }
    b.in1 = true;
    b.in2 = false;
    EXPECT_DOUBLE_EQ(b.drive_volts(), 22.0);
    b.in1 = false;
    b.in2 = true;
    EXPECT_DOUBLE_EQ(b.drive_volts(), -22.0);
}

// The 1Y falls (as INT0/INT1 trigger) at the revolutions given, sampled every 1e-5 revolution over one turn.
std::vector<double> falls(const SlottedEncoder& e) {
    std::vector<double> out;
    bool last = e.y_at(0.0);
    for (int i = 1; i <= 100000; ++i) {
        const double rev = i * 1e-5;
        const bool y = e.y_at(rev);
        if (last && !y) out.push_back(rev);
        last = y;
    }
    return out;
}

// The motor disc: 30 slots (seed 002 §2.3), one fall per slot pitch, 1/30 rev apart; starting at a fall (phase
// 1/2), the next falls are at k/30.
TEST(SlottedEncoder, MotorDiscFallsEverySlot) {
    const std::vector<double> f = falls(SlottedEncoder(30.0, 0.5));
    ASSERT_EQ(f.size(), 30U);
    for (std::size_t k = 0; k < f.size(); ++k) EXPECT_NEAR(f[k], (k + 1) / 30.0, 1e-5);
}

// The index disc: half reflective, half black, one fall per revolution; phase -1/80 puts it at 1/2 + 1/80 rev.
TEST(SlottedEncoder, IndexDiscFallsOncePerRevolution) {
    const SlottedEncoder index(1.0, -1.0 / 80.0);
    const std::vector<double> f = falls(index);
    ASSERT_EQ(f.size(), 1U);
    EXPECT_NEAR(f[0], 0.5 + 1.0 / 80.0, 1e-5);
    EXPECT_TRUE(index.y_at(0.4));  // high (reflective half seen) for the half revolution before the fall
    EXPECT_FALSE(index.y_at(0.6));
}

// §2.3, §2.5.3: a pressed key joins its column to its row; rows are pulled up. '5' is column 2 (PB6), row 2 (PB2).
TEST(KeypadMatrix, PressedKeyPullsItsRowWithItsColumn) {
    KeypadMatrix m;
    const std::array<bool, 4> all_high{true, true, true, true};
    EXPECT_EQ(m.rows({false, false, false, false}), all_high);  // nothing pressed
    m.press('5');
    EXPECT_EQ(m.rows(all_high), all_high);  // its column not driven low
    EXPECT_EQ(m.rows({true, false, true, true}), (std::array<bool, 4>{true, false, true, true}));
    EXPECT_EQ(m.rows({false, true, true, true}), all_high);  // another column low
    m.release_all();
    EXPECT_EQ(m.rows({true, false, true, true}), all_high);
}

}  // namespace
