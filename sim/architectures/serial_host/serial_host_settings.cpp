#include "architectures/serial_host/serial_host_settings.hpp"

namespace cnc::sim {

void read_serial_host_settings(KeyReader& r, SerialHostSettings& s) {
    s.link.requested_baud = static_cast<std::uint32_t>(
        r.get_int("link.baud", s.link.requested_baud, 300, 921'600, "baud rate the host asks the CP2102 for"));
    s.link.ideal_baud = r.get_bool("link.ideal_baud", s.link.ideal_baud,
                                   "line at exactly the requested rate (false: the CP2102's 24 MHz divider rate)");
    s.link.usb_latency_ps = s_to_ps(
        1e-3 * r.get_float("link.usb_latency_ms", 1.0, 0.0, 1000.0, "host driver latency for received bytes, ms"));
    s.link.usb_frame_ps = s_to_ps(
        1e-6 * r.get_float("link.usb_frame_us", 1000.0, 1.0, 100000.0, "USB frame interval, us (full speed: 1000)"));

    s.sender.settle_ps =
        s_to_ps(r.get_float("host.settle_s", 0.3, 0.0, 60.0, "wait after opening the port, s (send_steps.py: 0.3)"));
    s.sender.init_gap_ps =
        s_to_ps(r.get_float("host.init_gap_s", 0.05, 0.0, 60.0, "wait after the init packet, s (send_steps.py: 0.05)"));
    s.sender.ack_timeout_ps = s_to_ps(
        r.get_float("host.ack_timeout_s", 10.0, 0.001, 1e5, "ACK timeout per motion packet, s (send_steps.py: 10)"));
    s.sender.packet_processing_ps = s_to_ps(1e-6 * r.get_float("host.packet_processing_us", 200.0, 0.0, 1e6,
                                                               "host work between an ACK and the next write, us"));
    s.sender.write_latency_ps = s_to_ps(
        1e-6 * r.get_float("host.write_latency_us", 100.0, 0.0, 1e6, "OS latency from write() to the USB request, us"));
    s.sender.continue_on_timeout =
        r.get_choice("host.on_timeout", "abort", {"abort", "continue"},
                     "after an ACK timeout: abort (the script's prompt answered N) or continue") == "continue";
}

}  // namespace cnc::sim
