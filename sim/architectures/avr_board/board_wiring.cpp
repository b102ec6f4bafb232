#include "architectures/avr_board/board_wiring.hpp"

#include "architectures/avr_board/board_faults.hpp"

namespace cnc::sim {

void wire_board(BoardWires& wires, uart::Cp2102& cp2102, avr::AvrCore& mcu, MachinePins& pins,
                BoardLineFaults* faults) {
    if (faults != nullptr) {
        faults->wire(wires, cp2102, mcu);
    } else {
        cp2102.txd(wires.uart_rx);
        mcu.txd(wires.uart_tx);
    }
    cp2102.rxd(wires.uart_tx);
    mcu.step_x(pins.step_x);
    mcu.dir_x(pins.dir_x);
    mcu.en_x(pins.n_enbl_x);
    mcu.step_y(pins.step_y);
    mcu.dir_y(pins.dir_y);
    mcu.en_y(pins.n_enbl_y);
    mcu.head(pins.laser);
    mcu.rxd(wires.uart_rx);
}

MachinePinClocks board_pin_clocks(const avr::AvrCore& mcu) {
    const std::optional<std::int64_t> hz = mcu.chip().clock().grid_hz();
    return {hz, hz};
}

std::vector<TracedPin> board_traced_pins(const BoardWires& wires, const avr::AvrCore& mcu) {
    return {{&wires.uart_rx, "link", std::nullopt}, {&wires.uart_tx, "link", mcu.chip().clock().grid_hz()}};
}

void watch_board_lines(EdgeRecorder& rec, const BoardWires& wires) {
    for (const sc_core::sc_signal<bool>* sig : {&wires.uart_rx, &wires.uart_tx}) rec.watch(*sig, sig->basename());
}

void take_board_lines(EdgeRecorder& rec, DrivenPins& pins, std::map<std::string, EdgeLog>& lines) {
    for (const char* pin : {"uart_rx", "uart_tx"}) lines[pin] = rec.take(pin);
    for (const char* pin : {"n_enbl_x", "n_enbl_y"}) lines[pin] = pins.take_raw(pin);
    lines["step_x_pin"] =
        pins.take_raw("step_x");  // the raw pins: a firmware's timers may toggle STEP while EN is high
    lines["step_y_pin"] = pins.take_raw("step_y");
}

}  // namespace cnc::sim
