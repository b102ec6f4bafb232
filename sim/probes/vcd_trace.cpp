#include "probes/vcd_trace.hpp"

#include <filesystem>

#include <sysc/kernel/sc_dynamic_processes.h>

#include "common/bad_input.hpp"

namespace cnc::sim {

namespace {
TimePs now_ps() { return static_cast<TimePs>(sc_core::sc_time_stamp().value()); }
}  // namespace

VcdTrace::VcdTrace(const std::string& path, std::int64_t timescale_fs, const std::vector<TracedPin>& pins,
                   const std::string& timescale_key) {
    std::vector<metrics::VcdSignal> signals;
    for (const TracedPin& p : pins) signals.push_back({p.signal->basename(), p.signal->read(), p.clock_hz});
    metrics::check_vcd_signals(timescale_fs, signals, timescale_key);  // before the file exists: a refusal leaves none

    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    if (!parent.empty() && !std::filesystem::is_directory(parent)) {
        throw BadInput(path, "the VCD file's folder does not exist");
    }
    m_file.open(path);
    if (!m_file) throw BadInput(path, "cannot write the VCD file");
    m_writer.emplace(m_file, timescale_fs, std::move(signals), timescale_key);

    for (std::size_t i = 0; i < pins.size(); ++i) {
        const sc_core::sc_signal<bool>* signal = pins[i].signal;
        sc_core::sc_spawn_options opts;
        opts.spawn_method();
        opts.dont_initialize();
        opts.set_sensitivity(&signal->value_changed_event());
        sc_core::sc_spawn([this, signal, i] { m_writer->change(now_ps(), i, signal->read()); },
                          (std::string("vcd_") + signal->basename()).c_str(), &opts);
    }
}

VcdTrace::~VcdTrace() { m_writer->finish(now_ps()); }

}  // namespace cnc::sim
