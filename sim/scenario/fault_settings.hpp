// Scenario keys of the faults put on a run's links ([faults]): seeded, reproducible disturbances that an
// architecture applies to the links it has (Architecture::fault_links); a fault asked of a link the chosen
// architecture lacks is refused.
#pragma once
#include "scenario/key_reader.hpp"
#include "uart/core/line_faults.hpp"
#include "uart/core/usb_spikes.hpp"

namespace cnc::sim {

// The host program held up once: from at_s for length_s of simulated time it neither writes nor reads its port.
struct HostStall {
    double at_s = 0.0;
    double length_s = 0.0;  // 0: none

    [[nodiscard]] bool any() const { return length_s > 0.0; }
};

struct FaultSettings {
    std::uint64_t seed = 1;     // of every fault's draws (faults.seed)
    uart::LineFaultRates uart;  // on both wires of a UART link
    uart::UsbSpikeRates usb_spikes;  // on both directions of a USB serial link
    double spi_ber = 0.0;            // on MOSI and MISO of an SPI link
    HostStall host_stall;
    double step_loss_rate = 0.0;  // on each DRV8825's STEP input (mech::Drv8825Config::step_loss_rate)

    [[nodiscard]] bool any() const {
        return uart.any() || usb_spikes.any() || spi_ber > 0.0 || host_stall.any() || step_loss_rate > 0.0;
    }
};

// `scenario_seed` is the default of faults.seed.
void read_fault_settings(KeyReader& r, std::uint64_t scenario_seed, FaultSettings& s);

}  // namespace cnc::sim
