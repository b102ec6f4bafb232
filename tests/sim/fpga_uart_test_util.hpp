// Runs a shipped fpga-uart scenario in this test process (one SystemC elaboration per process).
#pragma once
#include <string>
#include <vector>

#include "run/run.hpp"
#include "scenario/scenario.hpp"

namespace cnc::test {

// `keep_logs`: out.arch.input keeps every edge and tool sample, as --plots and --samples ask (the metrics otherwise
// stream and drop them as they go).
inline sim::RunOutcome run_shipped(const std::string& name, const std::vector<std::string>& sets = {},
                                   bool keep_logs = false) {
    const std::string path = std::string(CNC_SOURCE_DIR) + "/scenarios/fpga-uart/" + name + ".toml";
    // The design's step arithmetic on an exact clock (clock.ideal; docs/metrics.md "Clocks"); a test of the real
    // oscillator asks for clock.ideal=false after it.
    std::vector<std::string> all = {"clock.ideal=true"};
    all.insert(all.end(), sets.begin(), sets.end());
    sim::Scenario s = sim::load_scenario(path, all);
    s.keep_run_input = keep_logs;
    return sim::run_scenario(s);
}

inline std::vector<TimePs> diffs(const std::vector<TimePs>& t) {
    std::vector<TimePs> d;
    for (std::size_t i = 1; i < t.size(); ++i) d.push_back(t[i] - t[i - 1]);
    return d;
}

}  // namespace cnc::test
