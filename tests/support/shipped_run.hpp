// Runs a shipped scenario in this test process (one SystemC elaboration per process), on exact clocks.
#pragma once
#include <string>
#include <vector>

#include "run/run.hpp"
#include "scenario/scenario.hpp"

namespace cnc::test {

// scenarios/<folder>/<name>.toml with `sets` applied. The design's step arithmetic on an exact clock (clock.ideal;
// docs/metrics.md "Clocks"): a test of the real oscillator asks for clock.ideal=false in `sets`.
// `keep_run_input`: out.arch.input keeps every edge and tool sample, as --plots and --samples ask (the metrics
// otherwise stream and drop them as they go).
inline sim::RunOutcome run_on_exact_clock(const std::string& folder, const std::string& name,
                                          const std::vector<std::string>& sets, bool keep_run_input) {
    const std::string path = std::string(CNC_SOURCE_DIR) + "/scenarios/" + folder + "/" + name + ".toml";
    std::vector<std::string> all = {"clock.ideal=true"};
    all.insert(all.end(), sets.begin(), sets.end());
    sim::Scenario s = sim::load_scenario(path, all);
    s.keep_run_input = keep_run_input;
    return sim::run_scenario(s);
}

}  // namespace cnc::test
