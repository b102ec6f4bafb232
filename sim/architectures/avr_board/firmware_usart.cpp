#include "architectures/avr_board/firmware_usart.hpp"

#include <fmt/format.h>

#include "avr/avr_chip.hpp"

namespace cnc::sim {

namespace {

// Cycles run between looks at RXEN0: 100 us at 16 MHz, so the probe stops soon after the receiver is on.
constexpr avr::Cycle kProbeSliceCycles = 1600;

}  // namespace

std::string FirmwareUsart::text(double f_cpu_hz) const {
    return fmt::format(FMT_STRING("{:.1f} Bd (UBRR{} = {}, U2X{} = {:d}: {} cycles a bit at {:g} MHz)"), baud, n, ubrr,
                       n, u2x, bit_cycles, f_cpu_hz / 1e6);
}

std::optional<FirmwareUsart> probe_firmware_usart(const avr::AvrCoreConfig& cfg) {
    avr::AvrChip chip(cfg);
    const auto limit = static_cast<avr::Cycle>(kProbeS * static_cast<double>(chip.f_cpu_hz()));
    while (chip.cycle() < limit) {
        if (chip.run_until(chip.cycle() + kProbeSliceCycles) != avr::ChipState::Running) break;
        (void)chip.take_events(chip.cycle());  // the pins are not watched here
        if (!chip.usart().rx_enabled_at(chip.cycle())) continue;
        const avr::UsartUnit& u = chip.usart();
        FirmwareUsart f;
        f.bit_cycles = u.bit_cycles();
        f.baud = chip.rx_clock().baud();
        f.ubrr = u.ubrrh() << 8 | u.ubrrl();
        constexpr std::int64_t kCyclesPerBitU2x = 8;  // Table 20-1: 8 (UBRR0 + 1) cycles a bit with U2X0 = 1
        f.u2x = f.bit_cycles == kCyclesPerBitU2x * (f.ubrr + 1);
        if (chip.mcu().mcu == avr::Mcu::Atmega16) f.n.clear();
        return f;
    }
    return std::nullopt;
}

}  // namespace cnc::sim
