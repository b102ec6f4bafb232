// Pin map parsing (avr.pins): the MCU's port pins (ATmega328P or ATmega16) and the machine signals they carry.
#include <gtest/gtest.h>

#include "avr/core/pin_map.hpp"
#include "common/bad_input.hpp"

using namespace cnc::avr;

namespace {

std::string error_of(const std::string& text) {
    try {
        (void)parse_pin_map(text, "s.toml: avr.pins");
    } catch (const cnc::BadInput& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(AvrPinMap, DefaultIsSeed003) {
    const PinMap m = default_pin_map();
    EXPECT_EQ(m.to_string(), "step_x=PD6,dir_x=PB0,en_x=PB2,step_y=PB3,dir_y=PB5,en_y=PB4,head=PB1");
    EXPECT_EQ(m.pins.size(), 7U);
}

// Seed 003 §5.6's board (avr.variant = "timer1-y"): STEP_Y on OC1A (PB1), the head on OC2A's pin (PB3); entries
// override it as they override the seed's.
TEST(AvrPinMap, TimerOneYMovesStepYAndTheHead) {
    const PinMap m = timer1_y_pin_map();
    EXPECT_EQ(m.to_string(), "step_x=PD6,dir_x=PB0,en_x=PB2,step_y=PB1,dir_y=PB5,en_y=PB4,head=PB3");
    validate(m, "t");
    EXPECT_EQ(parse_pin_map("head=PC0", "w", timer1_y_pin_map()).to_string(),
              "step_x=PD6,dir_x=PB0,en_x=PB2,step_y=PB1,dir_y=PB5,en_y=PB4,head=PC0");
}

TEST(AvrPinMap, ParsesPinNames) {
    EXPECT_EQ(parse_pin("PD6", ""), (Pin{'D', 6}));
    EXPECT_EQ(parse_pin(" pb3 ", ""), (Pin{'B', 3}));
    EXPECT_EQ(parse_pin("PC6", ""), (Pin{'C', 6}));
    EXPECT_EQ(parse_pin("PB7", ""), (Pin{'B', 7}));
    EXPECT_EQ(parse_pin("PD2", "").name(), "PD2");
}

TEST(AvrPinMap, EntriesOverrideTheDefault) {
    const PinMap m = parse_pin_map("step_x = PD5, DIR_X=pc0", "w");
    EXPECT_EQ(m.at("step_x"), (Pin{'D', 5}));
    EXPECT_EQ(m.at("dir_x"), (Pin{'C', 0}));
    EXPECT_EQ(m.at("head"), (Pin{'B', 1}));
    EXPECT_EQ(parse_pin_map("", "w").to_string(), default_pin_map().to_string());
}

TEST(AvrPinMap, RejectsPinsThatDoNotExist) {
    const std::string e9 = error_of("step_x=PE9");
    EXPECT_NE(e9.find("s.toml: avr.pins"), std::string::npos);
    EXPECT_NE(e9.find("'PE9'"), std::string::npos);
    EXPECT_NE(e9.find("PB0..PB7, PC0..PC6, PD2..PD7"), std::string::npos);
    EXPECT_NE(error_of("step_x=PB8").find("'PB8' does not exist"), std::string::npos);
    EXPECT_NE(error_of("step_x=PC7").find("'PC7' does not exist"), std::string::npos);
    EXPECT_NE(error_of("step_x=PD1").find("TXD"), std::string::npos);
    EXPECT_NE(error_of("step_x=PD0").find("RXD"), std::string::npos);
    EXPECT_NE(error_of("step_x=D6").find("not a port pin name"), std::string::npos);
    EXPECT_NE(error_of("step_x=PB10").find("not a port pin name"), std::string::npos);
}

TEST(AvrPinMap, RejectsUnknownSignalsAndClashes) {
    const std::string unknown = error_of("spindle=PB1");
    EXPECT_NE(unknown.find("unknown signal 'spindle'"), std::string::npos);
    EXPECT_NE(unknown.find("step_x, dir_x, en_x, step_y, dir_y, en_y, head"), std::string::npos);
    EXPECT_NE(error_of("step_x").find("not signal=pin"), std::string::npos);
    EXPECT_NE(error_of("step_x=PD5,step_x=PD4").find("mapped twice"), std::string::npos);
    EXPECT_NE(error_of("step_x=PB1").find("'head' and 'step_x' are both on PB1"), std::string::npos);
}

// grbl's board: one stepper-disable pin for both drivers (cpu_map.h STEPPERS_DISABLE_BIT 0), so the two enables may
// share a pin; any other pair still may not.
TEST(AvrPinMap, GrblsMapSharesOneEnablePin) {
    const PinMap m = grbl_pin_map();
    EXPECT_EQ(m.to_string(), "step_x=PD2,dir_x=PD5,en_x=PB0,step_y=PD3,dir_y=PD6,en_y=PB0,head=PB3");
    EXPECT_NO_THROW(validate(m, "grbl"));
    EXPECT_NO_THROW((void)parse_pin_map("en_x=PC0,en_y=PC0", "s.toml: avr.pins"));
    EXPECT_NE(error_of("en_x=PC1,dir_y=PC1").find("'dir_y' and 'en_x' are both on PC1"), std::string::npos);
}

// The ATmega16 (avr.mcu = "atmega16") has ports A to D with 8 pins each (doc2466 "Pin Configurations"); the
// ATmega328P has no port A and no PC7. Our grbl map for it keeps every signal on PORTA but the laser on OC2 (PD7).
TEST(AvrPinMap, PinsAreTheChosenMcus) {
    EXPECT_EQ(parse_pin("PA0", "", Mcu::Atmega16), (Pin{'A', 0}));
    EXPECT_EQ(parse_pin("PC7", "", Mcu::Atmega16), (Pin{'C', 7}));
    const auto error_for = [](const std::string& text, Mcu mcu) {
        try {
            (void)parse_pin_map(text, "s.toml: avr.pins", default_pin_map(), mcu);
        } catch (const cnc::BadInput& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(error_for("step_x=PA0", Mcu::Atmega328p).find("'PA0' names a port the ATmega328P does not have"),
              std::string::npos);
    const std::string e = error_for("head=PE2", Mcu::Atmega16);
    EXPECT_NE(e.find("'PE2' names a port the ATmega16 does not have (ATmega16 pins: PA0..PA7, PB0..PB7, PC0..PC7, "
                     "PD2..PD7)"),
              std::string::npos)
        << e;
    EXPECT_NE(error_for("step_x=PD1", Mcu::Atmega16).find("TXD"), std::string::npos);
    const PinMap m = grbl_atmega16_pin_map();
    EXPECT_EQ(m.to_string(), "step_x=PA0,dir_x=PA2,en_x=PA4,step_y=PA1,dir_y=PA3,en_y=PA4,head=PD7");
    EXPECT_NO_THROW(validate(m, "grbl", Mcu::Atmega16));
    EXPECT_THROW(validate(m, "grbl", Mcu::Atmega328p), cnc::BadInput);
}
