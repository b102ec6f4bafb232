#include "host/core/cad2g/firmware_busy.hpp"

#include <algorithm>

namespace cnc::host::cad2g {

double motion_s(const Motion& m, TimerClock x, TimerClock y) {
    const auto cycles = [](std::uint16_t count, std::uint16_t ocr, TimerClock clk) {
        return static_cast<double>(count) * static_cast<double>(step_period_cycles(ocr, clk));
    };
    const double x_cycles = m.y_counted ? 0.0 : cycles(m.count_x, m.ocr_x.value, x);
    const double y_cycles = cycles(m.y_counted ? m.count_x : m.count_y, m.ocr_y.value, y);
    return std::max(x_cycles, y_cycles) / x.f_cpu_hz;
}

std::vector<double> motion_before_next_confirm_s(const Plan& plan, const std::vector<Transfer>& transfers) {
    const TimerClock clk = plan.timer_x;
    std::vector<double> out;
    out.reserve(transfers.size());
    for (const Transfer& t : transfers) {
        const Command& c = plan.commands[t.command];
        const bool arc = c.id == CommandId::G02 || c.id == CommandId::G03;
        double s = 0.0;
        if (!arc && t.motion >= 0) {
            s = motion_s(c.motions[static_cast<std::size_t>(t.motion)], clk, plan.timer_y);
        } else if (arc && t.motion > 0) {
            s = motion_s(c.motions[static_cast<std::size_t>(t.motion) - 1], clk, plan.timer_y);
        } else if (arc && t.motion < 0 && !c.motions.empty()) {  // the terminator
            s = motion_s(c.motions.back(), clk, plan.timer_y);
        }
        out.push_back(s);
    }
    return out;
}

}  // namespace cnc::host::cad2g
