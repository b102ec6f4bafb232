#include "metrics/analyze_input.hpp"

#include <algorithm>

#include "common/bad_input.hpp"

namespace cnc::metrics {

namespace {

const EdgeLog& find_signal(const std::map<std::string, EdgeLog>& logs, const std::string& name,
                           const std::string& option) {
    const auto it = logs.find(name);
    if (it != logs.end()) return it->second;
    std::string available;
    for (const auto& [key, log] : logs) available += (available.empty() ? "" : ", ") + key;
    throw BadInput(option, "no 1-bit signal '" + name + "' in the trace; available: " +
                               (available.empty() ? "(none)" : available));
}

}  // namespace

RunInput analyze_input(const std::map<std::string, EdgeLog>& logs, const std::vector<AxisSignalNames>& axes,
                       std::optional<double> steps_per_mm) {
    if (steps_per_mm && !(*steps_per_mm > 0.0)) throw BadInput("--steps-per-mm", "must be greater than 0");
    RunInput in;
    std::optional<TimePs> first;
    std::optional<TimePs> last;
    const auto widen = [&](const EdgeLog& log) {
        if (log.edges.empty()) return;
        first = std::min(first.value_or(log.edges.front().t_ps), log.edges.front().t_ps);
        last = std::max(last.value_or(log.edges.back().t_ps), log.edges.back().t_ps);
    };
    for (const AxisSignalNames& names : axes) {
        AxisTrace trace;
        trace.step = find_signal(logs, names.step, "--step");
        if (!names.dir.empty()) trace.dir = find_signal(logs, names.dir, "--dir");
        trace.steps_per_mm = steps_per_mm.value_or(0.0);
        widen(trace.step);
        widen(trace.dir);
        in.axes.push_back(std::move(trace));
    }
    in.t_job_start_ps = first.value_or(0);
    in.t_job_end_ps = last.value_or(0);
    return in;
}

RunInput analyze_input(const std::map<std::string, EdgeLog>& logs, const std::string& step_name,
                       const std::string& dir_name, std::optional<double> steps_per_mm) {
    return analyze_input(logs, {AxisSignalNames{step_name, dir_name}}, steps_per_mm);
}

}  // namespace cnc::metrics
