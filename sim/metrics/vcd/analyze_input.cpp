#include "metrics/vcd/analyze_input.hpp"

#include <algorithm>

#include "common/bad_input.hpp"

namespace cnc::metrics {

namespace {

const EdgeLog& find_signal(const VcdContents& vcd, const std::string& filename, const std::string& option,
                           const std::string& name) {
    if (const EdgeLog* log = find_vcd_signal(vcd, name)) return *log;
    std::string available;
    for (const auto& [key, log] : vcd.signals) available += (available.empty() ? "" : ", ") + key;
    const auto other = vcd.other_variables.find(name);
    const std::string what = other == vcd.other_variables.end() ? "" : ": '" + name + "' is " + other->second;
    throw BadInput(filename + ": " + option + " " + name,
                   "no 1-bit signal '" + name + "' in the trace" + what +
                       "; 1-bit signals: " + (available.empty() ? "(none)" : available));
}

}  // namespace

EnableOption parse_enable_option(const std::string& text) {
    for (const auto& [suffix, level] :
         {std::pair{":active-low", EnableLevel::ActiveLow}, std::pair{":active-high", EnableLevel::ActiveHigh}}) {
        const std::string s = suffix;
        if (text.size() > s.size() && text.compare(text.size() - s.size(), s.size(), s) == 0) {
            return {text.substr(0, text.size() - s.size()), level};
        }
    }
    return {text, EnableLevel::ActiveLow};
}

RunInput analyze_input(const VcdContents& vcd, const std::string& filename, const std::vector<AxisSignalNames>& axes,
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
        trace.name = names.step;
        trace.step = find_signal(vcd, filename, "--step", names.step);
        if (!names.dir.empty()) trace.dir = find_signal(vcd, filename, "--dir", names.dir);
        if (!names.enable.empty()) {
            trace.step =
                enabled_steps(trace.step, find_signal(vcd, filename, "--enable", names.enable), names.enable_active);
        }
        trace.steps_per_mm = steps_per_mm.value_or(0.0);
        widen(trace.step);
        widen(trace.dir);
        in.axes.push_back(std::move(trace));
    }
    in.t_job_start_ps = first.value_or(0);
    in.t_job_end_ps = last.value_or(0);
    return in;
}

}  // namespace cnc::metrics
