// Runs a shipped atmega scenario in this test process (one SystemC elaboration per process).
#pragma once
#include <string>
#include <vector>

#include "support/edge_periods.hpp"
#include "support/shipped_run.hpp"

namespace cnc::test {

inline constexpr TimePs kAvrCyclePs = 62'500;  // 16 MHz

// STEP period of a CTC toggle timer at N = 1024: two matches of 1024 (OCR + 1) cycles.
constexpr TimePs step_period_ps(int ocr) {
    return 2 * 1024 * (ocr + 1) * kAvrCyclePs;
}

// out.arch.input keeps every edge and tool sample and out.arch.lines the link's and the raw pins' logs
// (atmega_streamed_test.cpp runs without them).
inline sim::RunOutcome run_atmega(const std::string& name, const std::vector<std::string>& sets = {}) {
    return run_on_exact_clock("atmega", name, sets, true);
}

inline bool has_warning(const sim::RunOutcome& out, const std::string& part) {
    for (const Warning& w : out.arch.warnings) {
        if (to_string(w).find(part) != std::string::npos) return true;
    }
    return false;
}

}  // namespace cnc::test
