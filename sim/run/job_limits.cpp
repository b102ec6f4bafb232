#include "run/job_limits.hpp"

#include <algorithm>
#include <cmath>

#include "common/bad_input.hpp"
#include "common/text_format.hpp"
#include "spi/core/spi_frame.hpp"

namespace cnc::sim {

namespace {

constexpr double kSecondsPerMinute = 60.0;

std::string place(const host::Program& p, const host::ProgrammedMove& m) {
    return p.filename + ":" + std::to_string(m.line);
}

// The largest |position| of an axis in mm.
double max_position_mm(const host::AxisMachine& axis) { return host::kMaxPositionSteps / axis.steps_per_mm(); }

std::string position_rule(const char* axis, const host::AxisMachine& m) {
    return format("; the farthest an axis may go is 2^30 - 1 steps, so that every move fits the int32 step counts: "
                  "%.10g mm on ",
                  max_position_mm(m)) +
           axis + format(" at %.10g steps/mm", m.steps_per_mm());
}

void check_position(const host::Program& p, const host::ProgrammedMove& m, const char* axis,
                    const host::AxisMachine& machine, double lo_mm, double hi_mm) {
    const double limit = max_position_mm(machine);
    const double worst = std::fabs(lo_mm) > std::fabs(hi_mm) ? lo_mm : hi_mm;
    if (!(std::fabs(worst) <= limit)) {
        throw BadInput(place(p, m), std::string(axis) + format(" %.10g mm is out of range", worst) +
                                        position_rule(axis, machine));
    }
}

// The slowest step rate the spi-fpga rate word can set: one step per 2^30 - 1 clocks.
void check_spi_feed(const host::Program& p, const host::ProgrammedMove& m, const Scenario& s) {
    if (m.kind == host::MotionKind::Rapid) return;
    const double length_mm = m.path.length_mm();
    const double dx = std::fabs(m.path.end.x_mm - m.path.start.x_mm);
    const double dy = std::fabs(m.path.end.y_mm - m.path.start.y_mm);
    // The faster axis on a line; on an arc each axis passes through the full path speed.
    const double share_x = m.path.is_arc ? 1.0 : dx / length_mm;
    const double share_y = m.path.is_arc ? 1.0 : dy / length_mm;
    const double mm_per_s = m.feed_mm_per_min / kSecondsPerMinute;
    const double steps_per_s = mm_per_s * std::max(share_x * s.machine.x.steps_per_mm(),
                                                    share_y * s.machine.y.steps_per_mm());
    const double slowest = spi::rate_for_period(spi::kMaxPeriodCycles, s.spi_fpga.fpga.clk_hz);
    if (steps_per_s < slowest) {
        throw BadInput(place(p, m), format("feed %.6g mm/min steps the leading axis %.6g times a second, slower "
                                           "than the spi-fpga rate word's slowest step (one per 2^30 - 1 clocks: ",
                                           m.feed_mm_per_min, steps_per_s) +
                                        format("%.4g steps/s at fpga_spi.clock_hz); raise F", slowest));
    }
}

// The model's message without its "machine: " place, which the scenario keys replace.
std::string numerator_problem(const BadInput& e) {
    const std::string what = e.what();
    const auto colon = what.find(": ");
    return colon == std::string::npos ? what : what.substr(colon + 2);
}

}  // namespace

void check_job_limits(const host::Program& p, const Scenario& s) {
    double job_s = 0.0;
    std::size_t wait = 0;
    for (std::size_t i = 0; i < p.moves.size(); ++i) {
        const host::ProgrammedMove& m = p.moves[i];
        const geom::Box box = m.path.bounds();
        check_position(p, m, "X", s.machine.x, box.min.x_mm, box.max.x_mm);
        check_position(p, m, "Y", s.machine.y, box.min.y_mm, box.max.y_mm);
        const bool x_finer = s.machine.x.steps_per_mm() >= s.machine.y.steps_per_mm();
        const host::AxisMachine& finer = x_finer ? s.machine.x : s.machine.y;
        if (m.path.is_arc && !(m.path.radius_mm() <= max_position_mm(finer))) {
            throw BadInput(place(p, m), format("arc radius %.10g mm (I, J or R) is out of range", m.path.radius_mm()) +
                                            position_rule(x_finer ? "X" : "Y", finer));
        }
        for (; wait < p.waits.size() && p.waits[wait].before_move <= i; ++wait) job_s += p.waits[wait].seconds;
        job_s += m.path.length_mm() / m.feed_mm_per_min * kSecondsPerMinute;
        if (!(job_s <= kMaxJobS)) {
            throw BadInput(place(p, m), format("the job reaches %.6g s of machine time here (at its feeds, with its "
                                               "dwells and pauses), more than the longest job simulated, %g s "
                                               "(11.6 days)",
                                               job_s, kMaxJobS));
        }
        if (s.architecture == "spi-fpga") check_spi_feed(p, m, s);
    }
    for (; wait < p.waits.size(); ++wait) {
        job_s += p.waits[wait].seconds;
        if (!(job_s <= kMaxJobS)) {
            throw BadInput(p.filename + ":" + std::to_string(p.waits[wait].line),
                           format("the job reaches %.6g s of machine time with this wait, more than the longest job "
                                  "simulated, %g s (11.6 days)",
                                  job_s, kMaxJobS));
        }
    }
}

void check_numerators(const Scenario& s) {
    if (!s.numerator_from_machine) return;
    for (const auto& [axis, machine] : {std::pair{"x", &s.machine.x}, std::pair{"y", &s.machine.y}}) {
        try {
            (void)host::numerator(machine->steps_per_mm(), s.fpga.clk_hz);
        } catch (const BadInput& e) {
            const std::string p = std::string("machine.") + axis + ".";
            throw BadInput(s.file + ": " + p + "steps_per_mm (or " + p + "step_angle_deg, microsteps and the "
                               "transmission keys), fpga.clock_hz",
                           format("%.10g steps/mm: ", machine->steps_per_mm()) + numerator_problem(e) +
                               "; host.numerator = \"seed-constant\" sends the script's constant instead");
        }
    }
}

}  // namespace cnc::sim
