#include "architectures/serial_host/usb_faults.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace cnc::sim {

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

}  // namespace cnc::sim
