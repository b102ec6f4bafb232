// The bit rate the firmware's USART0 runs at, read before the run: the ELF is booted alone (AvrChip, no SystemC,
// RXD idle high) until it enables its receiver, and the rate is what UBRR0 and U2X0 give then (datasheet Table
// 20-1: f_cpu / (16 (UBRR0 + 1)), or / 8 with U2X0). A firmware sets its USART up at start (seed 003's usart_init
// within its first hundred cycles, grbl's serial_init first thing in main), so kProbeS of CPU time is far more
// than it needs; one that has not enabled its receiver by then is left to the checks during the run.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include "avr/core/avr_config.hpp"

namespace cnc::sim {

inline constexpr double kProbeS = 0.1;  // 1.6 M cycles at 16 MHz: about 10 ms of wall time

struct FirmwareUsart {
    double baud = 0.0;
    std::int64_t bit_cycles = 0;  // CPU cycles per bit
    int ubrr = 0;
    bool u2x = false;
    std::string n = "0";  // the register names' USART number: "0" on the ATmega328P (UBRR0), none on the ATmega16

    // "58 823.5 Bd (UBRR0 = 16, U2X0 = 0: 272 cycles a bit at 16 MHz)"
    [[nodiscard]] std::string text(double f_cpu_hz) const;
};

// Throws BadInput for a missing or wrong ELF (as AvrCore does); nullopt if the receiver stays off for kProbeS.
[[nodiscard]] std::optional<FirmwareUsart> probe_firmware_usart(const avr::AvrCoreConfig& cfg);

}  // namespace cnc::sim
