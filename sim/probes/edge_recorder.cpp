#include "probes/edge_recorder.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

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

std::size_t EdgeRecorder::index_of(const std::string& pin_name) const {
    for (std::size_t i = 0; i < m_probes.size(); ++i) {
        if (m_probes[i].log.name == pin_name) return i;
    }
    throw std::out_of_range("no probe on pin " + pin_name);
}

const EdgeLog& EdgeRecorder::log(const std::string& pin_name) const {
    return m_probes[index_of(pin_name)].log;
}

EdgeLog EdgeRecorder::take(const std::string& pin_name) {
    EdgeLog& log = m_probes[index_of(pin_name)].log;
    EdgeLog out{log.name, log.initial, std::move(log.edges)};
    log.edges.clear();
    return out;
}

EdgeLog EdgeRecorder::take_before(const std::string& pin_name, TimePs t_ps) {
    return m_probes[index_of(pin_name)].log.take_before(t_ps);
}

}  // namespace cnc::sim
