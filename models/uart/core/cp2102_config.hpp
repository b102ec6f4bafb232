// The CP2102 USB-to-UART bridge as the host opens it: the requested baud rate, the frame format, the USB frame
// and driver latency, and the chip's FIFO sizes (CP2102 data sheet); the host's latency spikes, when a study asks for
// them.
#pragma once
#include <cstddef>
#include <cstdint>

#include "common/units.hpp"
#include "uart/core/uart_frame.hpp"
#include "uart/core/usb_spikes.hpp"
#include "uart/core/usb_timing.hpp"

namespace cnc::uart {

struct Cp2102Config {
    std::uint32_t requested_baud = 115'200;      // seed 000 §4.2
    bool ideal_baud = false;                     // true: the line runs at exactly the requested rate
    FrameFormat format = kFormat8N1;             // seed 000 §4.2: 8N1
    TimePs usb_frame_ps = kUsbFullSpeedFramePs;  // the CP2102 is full-speed only: SOF every 1 ms
    TimePs usb_latency_ps = kPsPerMs;            // host driver latency for received data (link.usb_latency_ms)
    std::size_t tx_fifo_bytes = 640;             // CP2102 data sheet: 640-byte transmit buffer
    std::size_t rx_fifo_bytes = 576;             // CP2102 data sheet: 576-byte receive buffer
    UsbSpikeRates usb_spikes;                    // the host's latency spikes (faults.usb_spike_*); none by default
    std::uint64_t usb_spike_seed = 1;            // their draws (faults.seed)
};

}  // namespace cnc::uart
