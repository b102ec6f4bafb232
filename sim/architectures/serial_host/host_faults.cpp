#include "architectures/serial_host/host_faults.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace cnc::sim {

nlohmann::json faulty_line_json(const uart::FaultyLineStats& line) {
    return {{"frames", line.frames},
            {"frames_hit", line.frames_hit},
            {"frames_lost", line.frames_lost},
            {"bits_inverted", line.bits_inverted}};
}

uart::Cp2102Config with_usb_spikes(uart::Cp2102Config link, const FaultSettings& f) {
    link.usb_spikes = f.usb_spikes;
    link.usb_spike_seed = f.seed;
    return link;
}

void report_usb_spikes(const FaultSettings& f, const uart::Cp2102& cp2102, ArchRun& run) {
    if (!f.usb_spikes.any()) return;
    const uart::Cp2102Stats& st = cp2102.stats();
    run.details["usb_spikes"] = {
        {"rate", f.usb_spikes.rate},
        {"mean_ms", ps_to_s(f.usb_spikes.mean_ps) * 1e3},
        {"to_chip", {{"frames_delayed", st.usb_spikes_out}, {"delay_ms", ps_to_s(st.usb_spike_delay_out_ps) * 1e3}}},
        {"to_host", {{"frames_delayed", st.usb_spikes_in}, {"delay_ms", ps_to_s(st.usb_spike_delay_in_ps) * 1e3}}}};
    run.details_text += fmt::format(
        FMT_STRING("USB latency spikes ({:g} of the frames, mean {:g} ms): {} frames of data to the "
                   "CP2102 delayed {:.3f} ms in all, {} to the host {:.3f} ms\n"),
        f.usb_spikes.rate, ps_to_s(f.usb_spikes.mean_ps) * 1e3, st.usb_spikes_out,
        ps_to_s(st.usb_spike_delay_out_ps) * 1e3, st.usb_spikes_in, ps_to_s(st.usb_spike_delay_in_ps) * 1e3);
}

host::StallWindow stall_window(const HostStall& stall) {
    if (!stall.any()) return {};
    const TimePs from_ps = s_to_ps(stall.at_s);
    return {from_ps, from_ps + s_to_ps(stall.length_s)};
}

nlohmann::json host_stall_json(const HostStall& stall, TimePs held_ps) {
    return {{"at_s", stall.at_s}, {"length_s", stall.length_s}, {"host_held_up_s", ps_to_s(held_ps)}};
}

std::string host_stall_text(const HostStall& stall, TimePs held_ps) {
    return fmt::format(FMT_STRING("  host stall of {:.3f} s at {:.3f} s: held the host program up {:.3f} s\n"),
                       stall.length_s, stall.at_s, ps_to_s(held_ps));
}

void report_host_stall(const HostStall& stall, TimePs held_ps, ArchRun& run) {
    if (!stall.any()) return;
    run.details["faults"]["host_stall"] = host_stall_json(stall, held_ps);
    run.details_text += host_stall_text(stall, held_ps);
}

}  // namespace cnc::sim
