// Runs a shipped fpga-uart scenario in this test process (one SystemC elaboration per process).
#pragma once
#include <string>
#include <vector>

#include "run/run.hpp"
#include "scenario/scenario.hpp"

namespace cnc::test {

inline sim::RunOutcome run_shipped(const std::string& name, const std::vector<std::string>& sets = {}) {
    const std::string path = std::string(CNC_SOURCE_DIR) + "/scenarios/fpga-uart/" + name + ".toml";
    return sim::run_scenario(sim::load_scenario(path, sets));
}

inline std::vector<TimePs> diffs(const std::vector<TimePs>& t) {
    std::vector<TimePs> d;
    for (std::size_t i = 1; i < t.size(); ++i) d.push_back(t[i] - t[i - 1]);
    return d;
}

}  // namespace cnc::test
