#include "metrics/report/zero_notes.hpp"

#include <nlohmann/json.hpp>

namespace cnc::metrics {

namespace {

bool is_zero(const nlohmann::json& report, const char* pointer) {
    const nlohmann::json::json_pointer p(pointer);
    return report.contains(p) && report.at(p).is_number() && report.at(p).get<double>() == 0.0;
}

}  // namespace

std::vector<std::string> zero_by_construction(const nlohmann::json& report) {
    std::vector<std::string> notes;
    if (!is_zero(report, "/metrics/pulse/tie_max_ns") || !is_zero(report, "/metrics/pulse/jitter_pp_max_ns")) {
        return notes;
    }
    const nlohmann::json clock = report.value("clock", nlohmann::json());
    if (clock.is_null()) {
        notes.emplace_back(
            "TIE and period jitter are 0 by construction: no clock times the STEP edges, each is "
            "placed at its computed time.");
    } else if (clock.value("jitter_rms_ps", 0.0) == 0.0) {
        notes.emplace_back(
            "TIE and period jitter are 0 by construction: every STEP edge falls on an edge of a "
            "clock without jitter (clock.ideal, or a clock jitter of 0 ps), and the periods of a run "
            "are a whole number of its cycles.");
    }
    return notes;
}

}  // namespace cnc::metrics
