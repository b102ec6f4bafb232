// Runs a shipped fpga-uart scenario in this test process (one SystemC elaboration per process).
#pragma once
#include <string>
#include <vector>

#include "support/edge_periods.hpp"
#include "support/shipped_run.hpp"

namespace cnc::test {

// `keep_logs`: run_on_exact_clock's keep_run_input.
inline sim::RunOutcome run_shipped(const std::string& name, const std::vector<std::string>& sets = {},
                                   bool keep_logs = false) {
    return run_on_exact_clock("fpga-uart", name, sets, keep_logs);
}

}  // namespace cnc::test
