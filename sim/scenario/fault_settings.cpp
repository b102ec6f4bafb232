#include "scenario/fault_settings.hpp"

#include <limits>

namespace cnc::sim {

void read_fault_settings(KeyReader& r, std::uint64_t scenario_seed, FaultSettings& s) {
    const std::uint64_t seed = static_cast<std::uint64_t>(
        r.get_int("faults.seed", static_cast<std::int64_t>(scenario_seed), 0, std::numeric_limits<std::int64_t>::max(),
                  "seed of every fault draw (default: scenario.seed); the same seed gives the same faults"));
    s.seed = seed;
    s.uart.ber = r.get_float("faults.uart_ber", 0.0, 0.0, 0.5,
                             "bit error rate on each wire of a UART link: every bit of a frame (start and stop bits "
                             "too) inverted with this probability, independently; 0: none");
    s.uart.frame_loss_rate = r.get_float("faults.uart_frame_loss_rate", 0.0, 0.0, 1.0,
                                         "fraction of the frames on each wire of a UART link lost whole (the line "
                                         "held idle for the frame); 0: none");
    s.spi_ber = r.get_float("faults.spi_ber", 0.0, 0.0, 0.5,
                            "bit error rate on MOSI and MISO of an SPI link: every bit the receiving end samples "
                            "inverted with this probability, independently; 0: none");
    s.usb_spikes.rate = r.get_float("faults.usb_spike_rate", 0.0, 0.0, 1.0,
                                    "fraction of the 1 ms USB frames, each direction, in which the host's USB stack "
                                    "delays the serial link's data by a latency spike (faults.usb_spike_mean_ms); "
                                    "0: none");
    s.usb_spikes.mean_ps = s_to_ps(
        1e-3 *
        r.get_float(
            "faults.usb_spike_mean_ms", 10.0, 0.001, 1000.0,
            "mean length of a USB latency spike, ms: each spike's length is drawn from the exponential distribution of "
            "this mean"));
    s.host_stall.at_s = r.get_float("faults.host_stall_at_s", 0.0, 0.0, 1e6,
                                    "start of a host stall, s of simulated time (faults.host_stall_s long)");
    s.host_stall.length_s = r.get_float("faults.host_stall_s", 0.0, 0.0, 1e6,
                                        "length of a host stall: the host program neither writes nor reads its port "
                                        "(another process, a USB reset), s; 0: none");
    s.step_loss_rate = r.get_float("faults.step_loss_rate", 0.0, 0.0, 1.0,
                                   "fraction of the STEP pulses lost on each DRV8825's input (a noisy or loose wire): "
                                   "each rising edge that would step is dropped with this probability; 0: none");
}

}  // namespace cnc::sim
