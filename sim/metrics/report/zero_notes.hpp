// Figures that are 0 by construction, not by luck: one line each saying why, for the run's summary and the
// comparison page (instead of a flat plot that reads as a measurement).
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace cnc::metrics {

// From a run's JSON report: its metrics and its "clock" object (null: no clock times the STEP edges).
[[nodiscard]] std::vector<std::string> zero_by_construction(const nlohmann::json& report);

}  // namespace cnc::metrics
