// Records the edges of watched pins into EdgeLogs (the simulated logic analyser the metrics read).
#pragma once
#include <cstddef>
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
    // Hands the log over after the simulation (its copy here is left empty): a long job's STEP logs are its
    // largest data, and a copy would double them.
    [[nodiscard]] EdgeLog take(const std::string& pin_name);
    // Hands over the edges before t_ps during the simulation (the level they leave becomes the kept log's initial
    // one), so that a long run's logs stay as short as the metrics need them.
    [[nodiscard]] EdgeLog take_before(const std::string& pin_name, TimePs t_ps);

private:
    struct Probe {
        const sc_core::sc_signal<bool>* signal;
        EdgeLog log;
    };
    void sample(Probe& probe);
    [[nodiscard]] std::size_t index_of(const std::string& pin_name) const;

    std::deque<Probe> m_probes;  // deque: stable addresses for the spawned methods
};

}  // namespace cnc::sim
