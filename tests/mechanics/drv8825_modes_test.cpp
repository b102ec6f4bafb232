#include <gtest/gtest.h>

#include <cmath>

#include "common/bad_input.hpp"
#include "mechanics/core/drv8825_current.hpp"
#include "mechanics/core/drv8825_modes.hpp"

using namespace cnc::mech;

TEST(Drv8825Modes, AllEightPinCombinations) {
    // {m2, m1, m0} -> microsteps (DRV8825 data sheet, TI SLVSA73)
    const int want[8] = {1, 2, 4, 8, 16, 32, 32, 32};
    for (int code = 0; code < 8; ++code) {
        const ModePins p{(code & 1) != 0, (code & 2) != 0, (code & 4) != 0};
        EXPECT_EQ(microsteps_for(p), want[code]) << "MODE2..0 = " << code;
    }
}

TEST(Drv8825Modes, InverseRoundTripsAndRejectsOtherValues) {
    for (int m : {1, 2, 4, 8, 16, 32}) EXPECT_EQ(microsteps_for(mode_pins_for(m)), m);
    const ModePins p32 = mode_pins_for(32);  // seed 000 §2.3, Fig. 2.7: M0=1 M1=0 M2=1
    EXPECT_TRUE(p32.m0);
    EXPECT_FALSE(p32.m1);
    EXPECT_TRUE(p32.m2);
    for (int bad : {0, 3, 64, -1}) EXPECT_THROW((void)mode_pins_for(bad), cnc::BadInput);
}

TEST(Drv8825Modes, IndexerCurrentsMatchTheDataSheetTable) {
    EXPECT_DOUBLE_EQ(electrical_step_deg(32), 2.8125);
    EXPECT_DOUBLE_EQ(electrical_step_deg(1), 90.0);
    // First octant of the 1/32 indexer table (TI SLVSA73), from 0 deg (units -16) to the 45 deg home state (units 0).
    const int a[17] = {100, 100, 100, 99, 98, 97, 96, 94, 92, 90, 88, 86, 83, 80, 77, 74, 71};
    const int b[17] = {0, 5, 10, 15, 20, 24, 29, 34, 38, 43, 47, 51, 56, 60, 63, 67, 71};
    for (int k = 0; k <= 16; ++k) {
        const PhaseCurrents c = phase_currents(k - 16);
        EXPECT_EQ(std::lround(c.a_pct), a[k]) << "k=" << k;
        EXPECT_EQ(std::lround(c.b_pct), b[k]) << "k=" << k;
    }
    EXPECT_NEAR(phase_currents(0).a_pct, 70.71, 0.01);    // home
    EXPECT_NEAR(phase_currents(32).a_pct, -70.71, 0.01);  // one full step on: 135 deg
    EXPECT_NEAR(phase_currents(32).b_pct, 70.71, 0.01);
}

TEST(Drv8825Modes, NextIndexerPosition) {
    EXPECT_EQ(next_indexer_position(0, 32, 1), 1);
    EXPECT_EQ(next_indexer_position(0, 32, -1), -1);
    EXPECT_EQ(next_indexer_position(0, 1, 1), 32);
    EXPECT_EQ(next_indexer_position(0, 16, -1), -2);
    // Mode change mid-run (data sheet §8.3.5): 1/32 position 4 of the table (8.4375 deg = units -13), stepping
    // forward in 1/2 mode, goes to 1/2 position 2 (45 deg = units 0); backward to 0 deg (units -16).
    EXPECT_EQ(next_indexer_position(-13, 2, 1), 0);
    EXPECT_EQ(next_indexer_position(-13, 2, -1), -16);
    EXPECT_EQ(next_indexer_position(5, 1, 1), 32);
    EXPECT_EQ(next_indexer_position(5, 1, -1), 0);
    EXPECT_EQ(next_indexer_position(-32, 1, -1), -64);
}

TEST(Drv8825Current, TheChoppingCurrentIsVrefOverFiveTimesRsense) {
    // DRV8825 data sheet (TI SLVSA73) §8.3.4 Current Regulation, eq. 1: I_CHOP = V_xREF / (5 x R_SENSE). On the
    // Pololu carrier's 0.100 ohm sense resistors that is 2 A per volt of VREF (the A4988's formula, / 8 R_SENSE,
    // would give 1.25).
    for (const double vref_v : {0.1, 0.5, 0.85, 1.25}) {
        EXPECT_NEAR(current_limit_from_vref_a(vref_v, 0.100), 2.0 * vref_v, 1e-12) << vref_v << " V";
    }
    EXPECT_NEAR(current_limit_from_vref_a(1.0, 0.200), 1.0, 1e-12);
    EXPECT_NEAR(current_limit_from_vref_a(0.33, 0.330), 0.2, 1e-12);
    EXPECT_THROW((void)current_limit_from_vref_a(1.0, 0.0), cnc::BadInput);
}
