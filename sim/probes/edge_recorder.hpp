// Records the edges of watched pins into EdgeLogs (the simulated logic analyser the metrics read).
#pragma once
#include <deque>
#include <string>
#include <vector>

#include <systemc>

#include "common/edge_log.hpp"

namespace cnc::sim {

class EdgeRecorder : public sc_core::sc_module {
public:
    explicit EdgeRecorder(const sc_core::sc_module_name& name);

    // Watches `signal` under `pin_name`; call before the simulation starts.
    void watch(const sc_core::sc_signal<bool>& signal, const std::string& pin_name);
    [[nodiscard]] const EdgeLog& log(const std::string& pin_name) const;

private:
    struct Probe {
        const sc_core::sc_signal<bool>* signal;
        EdgeLog log;
    };
    void sample(Probe& probe);

    std::deque<Probe> m_probes;  // deque: stable addresses for the spawned methods
};

}  // namespace cnc::sim
