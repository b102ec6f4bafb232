// Which port pins of the MCU (ATmega328P or ATmega16) carry the machine's signals (STEP/DIR/EN per axis, the tool
// head), so that any firmware, not only seed 003's, can drive the modelled machine. Scenario syntax (`avr.pins`):
//     "step_x=PD6, dir_x=PB0, en_x=PB2, step_y=PB3, dir_y=PB5, en_y=PB4, head=PB1"
// Entries not named keep seed 003's default; names are case-insensitive ("pd6" = "PD6").
#pragma once
#include <array>
#include <map>
#include <string>
#include <string_view>

#include "avr/core/mcu_map.hpp"

namespace cnc::avr {

struct Pin {
    char port = 'B';  // 'A' (ATmega16 only), 'B', 'C' or 'D'
    int bit = 0;      // 0..7

    [[nodiscard]] std::string name() const { return std::string{'P', port, static_cast<char>('0' + bit)}; }
    friend bool operator==(const Pin& a, const Pin& b) { return a.port == b.port && a.bit == b.bit; }
    friend bool operator!=(const Pin& a, const Pin& b) { return !(a == b); }
};

// The signals a pin map assigns, in the order AvrCore exposes them as ports.
inline constexpr std::array<std::string_view, 7> kPinSignals{"step_x", "dir_x", "en_x", "step_y",
                                                             "dir_y",  "en_y",  "head"};

// "PD6" -> {D, 6}, a pin the MCU has (McuMap::ports): the ATmega328P has PB0..PB7, PC0..PC6 and PD0..PD7
// (datasheet §1.1 pin configurations; PB6/PB7 are the crystal pins and PC6 is RESET on an Arduino board, but they
// are port bits all the same), the ATmega16 PA0..PD7 (doc2466 "Pin Configurations"). PD0/PD1 are RXD/TXD on both,
// reserved for the USART link. Anything else throws BadInput(where, ...) naming the text and the MCU.
[[nodiscard]] Pin parse_pin(std::string_view text, const std::string& where, Mcu mcu = Mcu::Atmega328p);

struct PinMap {
    std::map<std::string, Pin> pins;  // signal (one of kPinSignals) -> pin; always holds all seven

    [[nodiscard]] const Pin& at(std::string_view signal) const { return pins.at(std::string(signal)); }
    [[nodiscard]] std::string to_string() const;  // in the `avr.pins` syntax, signals in kPinSignals order
};

// Seed 003 §5.2.5: STEP_X PD6 (OC0A), DIR_X PB0, EN_X PB2 (active low), STEP_Y PB3 (OC2A), DIR_Y PB5,
// EN_Y PB4 (active low), head PB1 (OC1A, the servo / "HEADER" bit).
[[nodiscard]] PinMap default_pin_map();

// Seed 003 §5.6's proposed board (avr.variant = "timer1-y"): STEP_Y on PB1 (OC1A, Timer1), the head on PB3
// (OC2A's pin, Timer2's), the rest as default_pin_map().
[[nodiscard]] PinMap timer1_y_pin_map();

// grbl 1.1 on the ATmega328P (its cpu_map.h, the Arduino Uno pin-out): STEP X/Y PD2/PD3, DIR X/Y PD5/PD6, one
// stepper-disable pin PB0 for both drivers, the laser on the spindle PWM pin OC2A = PB3.
[[nodiscard]] PinMap grbl_pin_map();

// grbl has no port to the ATmega16; this is ours for the grbl-protocol firmware built for it: STEP X/Y PA0/PA1,
// DIR X/Y PA2/PA3, the shared disable PA4, the laser on OC2 = PD7 (Timer2's PWM, as grbl's spindle on the 328P).
// PORTA's only other function is the ADC, which is off from reset: the pins clash with none of the USART (PD0/PD1,
// XCK PB0), the compare outputs the firmware could use (OC0 PB3, OC1A/B PD5/PD4), INT0/INT1/INT2 (PD2, PD3, PB2),
// ICP1 (PD6), the SPI programming pins (PB4..PB7), JTAG (PC2..PC5, on with the factory fuses) or TOSC (PC6/PC7),
// and the STEP and DIR bits share a port as grbl's port masks want (doc2466 "Alternate Port Functions").
[[nodiscard]] PinMap grbl_atmega16_pin_map();

// Checks a map built in code: all seven signals, each on a pin the MCU has, no pin twice but for en_x and en_y (one
// enable line to both drivers' nENBL, as grbl wires them). Throws BadInput.
void validate(const PinMap& map, const std::string& where, Mcu mcu = Mcu::Atmega328p);

// Overrides the default map with "signal=pin" entries separated by commas. Unknown signals, bad pins (for `mcu`),
// a signal named twice or two signals on one pin (but en_x and en_y) throw BadInput(where, ...).
[[nodiscard]] PinMap parse_pin_map(std::string_view text, const std::string& where);
// The same over another default map (timer1_y_pin_map()).
[[nodiscard]] PinMap parse_pin_map(std::string_view text, const std::string& where, PinMap defaults,
                                   Mcu mcu = Mcu::Atmega328p);

}  // namespace cnc::avr
