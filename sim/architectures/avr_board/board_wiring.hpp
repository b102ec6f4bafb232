// The Arduino board as both architectures on it wire it: the CP2102's TXD to the ATmega328P's RXD and back, the
// MCU's pin-map outputs to the machine's STEP, DIR, nENBL and laser pins; their clocks and the link's lines for the
// VCD and the tests.
#pragma once
#include <map>
#include <string>
#include <vector>

#include <systemc>

#include "architectures/avr_board/driven_pins.hpp"
#include "avr/avr_core.hpp"
#include "probes/edge_recorder.hpp"
#include "run/controller.hpp"
#include "run/machine.hpp"
#include "uart/cp2102.hpp"

namespace cnc::sim {

// The link's wires (the machine's pins are the run's: run/machine.hpp); the VCD and the analyze scripts rely on the
// names (docs/architectures.md "Pins").
struct BoardWires {
    sc_core::sc_signal<bool> uart_rx{"uart_rx", true};  // CP2102 TXD -> PD0 RXD; idles high
    sc_core::sc_signal<bool> uart_tx{"uart_tx", true};  // PD1 TXD -> CP2102 RXD
};

class BoardLineFaults;

// `faults`: the link's wires through their faults (board_faults.hpp), or null for clean wires.
void wire_board(BoardWires& wires, uart::Cp2102& cp2102, avr::AvrCore& mcu, MachinePins& pins,
                BoardLineFaults* faults = nullptr);

// The AVR times every pin it drives; the CP2102 (uart_rx) starts its frames when USB delivers the bytes.
[[nodiscard]] MachinePinClocks board_pin_clocks(const avr::AvrCore& mcu);
[[nodiscard]] std::vector<TracedPin> board_traced_pins(const BoardWires& wires, const avr::AvrCore& mcu);
// The link's lines, watched with the whole logs only: only the tests read them.
void watch_board_lines(EdgeRecorder& rec, const BoardWires& wires);
// With the whole logs: the link's lines, the raw nENBL and the raw STEP pins (step_x_pin, step_y_pin).
void take_board_lines(EdgeRecorder& rec, DrivenPins& pins, std::map<std::string, EdgeLog>& lines);

}  // namespace cnc::sim
