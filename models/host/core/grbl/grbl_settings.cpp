#include "host/core/grbl/grbl_settings.hpp"

#include <map>

#include <fmt/format.h>

#include "common/bad_input.hpp"

namespace cnc::host::grbl {

namespace {

// grbl prints and parses settings as decimals; three decimals keep 160 steps/mm, 3000 mm/min and 1000 mm/s^2 exact.
std::string value_text(double v) {
    return fmt::format(FMT_STRING("{:.3f}"), v);
}

// "$N=value": N and the value's text; BadInput otherwise.
std::pair<int, std::string> parse_override(const std::string& text, const std::string& where) {
    const std::size_t eq = text.find('=');
    const auto bad = [&](const std::string& why) {
        throw BadInput(where, "'" + text + "' " + why + " (a grbl setting is \"$N=value\", e.g. \"$0=10\")");
    };
    if (text.size() < 4 || text[0] != '$' || eq == std::string::npos || eq < 2 || eq + 1 == text.size()) {
        bad("is not a setting");
    }
    int n = 0;
    for (std::size_t i = 1; i < eq; ++i) {
        if (text[i] < '0' || text[i] > '9') bad("has no setting number");
        n = n * 10 + (text[i] - '0');
    }
    return {n, text.substr(eq + 1)};
}

}  // namespace

std::vector<SendLine> machine_settings(const MachineModel& machine, bool laser_mode,
                                       const std::vector<std::string>& overrides, const std::string& where,
                                       const std::string& file) {
    std::map<int, std::pair<std::string, std::string>> by_number;  // N -> value text, what it comes from
    const AxisMachine* axes[2] = {&machine.x, &machine.y};
    const char* names[2] = {"machine.x", "machine.y"};
    for (int a = 0; a < 2; ++a) {
        const std::string axis = file + ": " + names[a];
        by_number[100 + a] = {value_text(axes[a]->steps_per_mm()), axis + " steps per mm"};
        by_number[110 + a] = {value_text(axes[a]->limits.max_velocity_mm_per_s * 60.0),
                              axis + ".max_velocity_mm_per_s x 60"};
        by_number[120 + a] = {value_text(axes[a]->limits.max_accel_mm_per_s2), axis + ".max_accel_mm_per_s2"};
    }
    by_number[32] = {laser_mode ? "1" : "0", file + ": the job's laser words"};
    for (const std::string& text : overrides) {
        auto [n, value] = parse_override(text, where);
        by_number[n] = {value, where};
    }
    std::vector<SendLine> out;
    for (const auto& [n, v] : by_number) out.push_back({fmt::format(FMT_STRING("${}={}"), n, v.first), v.second});
    return out;
}

}  // namespace cnc::host::grbl
