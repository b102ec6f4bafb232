// Builds the metrics input of `cncsim analyze` from the signals of a VCD: STEP/DIR pairs, no moves, no
// tool positions, so only the pulse and driver-timing metrics (and travel when steps/mm is known) apply.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "common/edge_log.hpp"
#include "metrics/run_input.hpp"

namespace cnc::metrics {

struct AxisSignalNames {
    std::string step;
    std::string dir;  // empty: no DIR signal (constant low)
};

// Axes are labelled x, y, z in the given order. The job window runs from the first to the last edge of
// the named signals. Throws cnc::BadInput("--step" or "--dir", ...) naming the available signals when a
// signal is missing, and BadInput("--steps-per-mm", ...) for a value <= 0.
[[nodiscard]] RunInput analyze_input(const std::map<std::string, EdgeLog>& logs,
                                     const std::vector<AxisSignalNames>& axes,
                                     std::optional<double> steps_per_mm = std::nullopt);

[[nodiscard]] RunInput analyze_input(const std::map<std::string, EdgeLog>& logs, const std::string& step_name,
                                     const std::string& dir_name, std::optional<double> steps_per_mm = std::nullopt);

}  // namespace cnc::metrics
