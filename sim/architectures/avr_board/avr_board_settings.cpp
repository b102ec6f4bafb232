#include "architectures/avr_board/avr_board_settings.hpp"

namespace cnc::sim {

namespace {

// seed 003 §5.2.4 runs the ATmega328P on an Arduino board at 16 MHz, as grbl 1.1 runs: the Uno clocks it from a
// ceramic resonator.
constexpr OscillatorPart kUnoResonator{
    "avr",  "16 MHz ceramic resonator of the Arduino Uno (Murata CSTCE16M0V53-R0)",
    5000.0, "Murata CERALOCK catalogue: initial tolerance +-0.5 %",
    10.0,   "no resonator data sheet gives it: our estimate, a few times a crystal oscillator's"};

}  // namespace

void read_avr_board_settings(KeyReader& r, AvrBoardSettings& s, const std::filesystem::path& base) {
    s.mcu = r.get_choice("avr.mcu", s.mcu, {"atmega328p", "atmega16"},
                         "the MCU on the board, as avr-gcc's -mmcu names it: atmega328p (seed 003's, grbl's) or "
                         "atmega16 (its USART, Timer0/1/2 and ports at their own registers; the firmware must be "
                         "built for it, and the seed 003 firmware of this build is not: give yours with "
                         "avr.firmware)");
    const std::string fw = r.get_string(
        "avr.firmware", "",
        "the MCU's firmware, an ELF or Intel HEX file built for avr.mcu, relative to the scenario; empty: seed "
        "003's firmware of this build for avr.variant on seed 003's board, and on grbl's an error that says how to "
        "build grbl");
    s.firmware = fw.empty() ? std::string() : (base / fw).lexically_normal().string();
    s.pins = r.get_string("avr.pins", "",
                          "pins of the machine signals on the MCU, \"signal=pin, ...\" (signals step_x dir_x "
                          "en_x step_y dir_y en_y head; en_x and en_y may share a pin); entries left out keep the "
                          "board's map: seed 003 §5.2.5 (step_x=PD6, dir_x=PB0, en_x=PB2, step_y=PB3, dir_y=PB5, "
                          "en_y=PB4, head=PB1; avr.variant = \"timer1-y\": step_y=PB1, head=PB3), or grbl 1.1's "
                          "cpu_map.h (step_x=PD2, dir_x=PD5, step_y=PD3, dir_y=PD6, en_x=en_y=PB0, head=PB3); on "
                          "grbl with avr.mcu = \"atmega16\" ours (step_x=PA0, dir_x=PA2, step_y=PA1, dir_y=PA3, "
                          "en_x=en_y=PA4, head=PD7)");
    s.quantum_cycles = static_cast<std::uint32_t>(
        r.get_int("avr.quantum_cycles", s.quantum_cycles, 1, 1'000'000,
                  "AVR cycles run ahead of SystemC time between replays of its pin changes (speed only: outputs "
                  "keep their exact cycle)"));
    read_oscillator_settings(r, kUnoResonator, 16'000'000, s.clock);
    s.fast_forward = read_fast_forward(r, "avr.fast_forward");
}

bool read_fast_forward(KeyReader& r, const std::string& key) {
    return r.get_bool(key, true,
                      "skip the iterations of the firmware's polling loops that change nothing up to the next timer, "
                      "USART or input event (speed only: every pin edge and byte keeps its exact cycle); false: "
                      "every cycle is executed");
}

}  // namespace cnc::sim
