#include "probes/edge_recorder.hpp"

#include <stdexcept>

#include <sysc/kernel/sc_dynamic_processes.h>

namespace cnc::sim {

EdgeRecorder::EdgeRecorder(const sc_core::sc_module_name& name) : sc_module(name) {}

void EdgeRecorder::watch(const sc_core::sc_signal<bool>& signal, const std::string& pin_name) {
    m_probes.push_back({&signal, EdgeLog{pin_name, signal.read(), {}}});
    Probe& probe = m_probes.back();
    sc_core::sc_spawn_options opts;
    opts.spawn_method();
    opts.dont_initialize();
    opts.set_sensitivity(&signal.value_changed_event());
    sc_core::sc_spawn([this, &probe] { sample(probe); }, ("rec_" + pin_name).c_str(), &opts);
}

void EdgeRecorder::sample(Probe& probe) {
    probe.log.add(static_cast<TimePs>(sc_core::sc_time_stamp().value()), probe.signal->read());
}

const EdgeLog& EdgeRecorder::log(const std::string& pin_name) const {
    for (const Probe& p : m_probes) {
        if (p.log.name == pin_name) return p.log;
    }
    throw std::out_of_range("no probe on pin " + pin_name);
}

}  // namespace cnc::sim
