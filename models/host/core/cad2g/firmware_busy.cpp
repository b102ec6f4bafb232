#include "host/core/cad2g/firmware_busy.hpp"

#include <algorithm>

namespace cnc::host::cad2g {

double motion_s(const Motion& m, TimerClock clk) {
    const double x_cycles =
        static_cast<double>(m.count_x) * static_cast<double>(step_period_cycles(m.ocr_x.value, clk));
    const double y_cycles =
        static_cast<double>(m.count_y) * static_cast<double>(step_period_cycles(m.ocr_y.value, clk));
    return std::max(x_cycles, y_cycles) / clk.f_cpu_hz;
}

std::vector<double> motion_before_next_confirm_s(const Plan& plan, const std::vector<Transfer>& transfers,
                                                 TimerClock clk) {
    std::vector<double> out;
    out.reserve(transfers.size());
    for (const Transfer& t : transfers) {
        const Command& c = plan.commands[t.command];
        const bool arc = c.id == CommandId::G02 || c.id == CommandId::G03;
        double s = 0.0;
        if (!arc && t.motion >= 0) {
            s = motion_s(c.motions[static_cast<std::size_t>(t.motion)], clk);
        } else if (arc && t.motion > 0) {
            s = motion_s(c.motions[static_cast<std::size_t>(t.motion) - 1], clk);
        } else if (arc && t.motion < 0 && !c.motions.empty()) {  // the terminator
            s = motion_s(c.motions.back(), clk);
        }
        out.push_back(s);
    }
    return out;
}

}  // namespace cnc::host::cad2g
