#include "run/job_limits.hpp"

#include <algorithm>
#include <cmath>

#include "common/bad_input.hpp"
#include "common/text_format.hpp"
#include "spi/core/spi_frame.hpp"

namespace cnc::sim {

namespace {

constexpr double kSecondsPerMinute = 60.0;

// The largest |position| of an axis in mm.
double max_position_mm(const host::AxisMachine& axis) { return host::kMaxPositionSteps / axis.steps_per_mm(); }

std::string position_rule(const char* axis, const host::AxisMachine& m) {
    return format("; the farthest an axis may go is 2^30 - 1 steps, so that every move fits the int32 step counts: "
                  "%.10g mm on ",
                  max_position_mm(m)) +
           axis + format(" at %.10g steps/mm", m.steps_per_mm());
}

void check_position(const std::string& where, const char* axis,
                    const host::AxisMachine& machine, double lo_mm, double hi_mm) {
    const double limit = max_position_mm(machine);
    const double worst = std::fabs(lo_mm) > std::fabs(hi_mm) ? lo_mm : hi_mm;
    if (!(std::fabs(worst) <= limit)) {
        throw BadInput(where, std::string(axis) + format(" %.10g mm is out of range", worst) +
                                        position_rule(axis, machine));
    }
}

// The slowest step rate the spi-fpga rate word can set: one step per 2^30 - 1 clocks.
void check_spi_feed(const std::string& where, const host::ProgrammedMove& m, const Scenario& s) {
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
        throw BadInput(where, format("feed %.6g mm/min steps the leading axis %.6g times a second, slower "
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

JobLimits::JobLimits(const Scenario& s, std::string filename) : m_s(s), m_file(std::move(filename)) {}

void JobLimits::check(const host::ProgrammedMove& m, std::size_t i, const std::vector<host::HostWait>& waits) {
    const std::string where = m_file + ":" + std::to_string(m.line);
    const geom::Box box = m.path.bounds();
    check_position(where, "X", m_s.machine.x, box.min.x_mm, box.max.x_mm);
    check_position(where, "Y", m_s.machine.y, box.min.y_mm, box.max.y_mm);
    const bool x_finer = m_s.machine.x.steps_per_mm() >= m_s.machine.y.steps_per_mm();
    const host::AxisMachine& finer = x_finer ? m_s.machine.x : m_s.machine.y;
    if (m.path.is_arc && !(m.path.radius_mm() <= max_position_mm(finer))) {
        throw BadInput(where, format("arc radius %.10g mm (I, J or R) is out of range", m.path.radius_mm()) +
                                  position_rule(x_finer ? "X" : "Y", finer));
    }
    for (; m_wait < waits.size() && waits[m_wait].before_move <= i; ++m_wait) m_job_s += waits[m_wait].seconds;
    m_job_s += m.path.length_mm() / m.feed_mm_per_min * kSecondsPerMinute;
    if (!(m_job_s <= kMaxJobS)) {
        throw BadInput(where, format("the job reaches %.6g s of machine time here (at its feeds, with its "
                                     "dwells and pauses), more than the longest job simulated, %g s "
                                     "(11.6 days)",
                                     m_job_s, kMaxJobS));
    }
    if (m_s.architecture == "spi-fpga") check_spi_feed(where, m, m_s);
}

void JobLimits::finish(const std::vector<host::HostWait>& waits) {
    for (; m_wait < waits.size(); ++m_wait) {
        m_job_s += waits[m_wait].seconds;
        if (!(m_job_s <= kMaxJobS)) {
            throw BadInput(m_file + ":" + std::to_string(waits[m_wait].line),
                           format("the job reaches %.6g s of machine time with this wait, more than the longest job "
                                  "simulated, %g s (11.6 days)",
                                  m_job_s, kMaxJobS));
        }
    }
}

void check_job_limits(const host::Program& p, const Scenario& s) {
    JobLimits limits(s, p.filename);
    for (std::size_t i = 0; i < p.moves.size(); ++i) limits.check(p.moves[i], i, p.waits);
    limits.finish(p.waits);
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
