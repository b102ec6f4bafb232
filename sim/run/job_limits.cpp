#include "run/job_limits.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "common/bad_input.hpp"

namespace cnc::sim {

namespace {

constexpr double kSecondsPerMinute = 60.0;

// The largest |position| of an axis in mm.
double max_position_mm(const host::AxisMachine& axis) {
    return host::kMaxPositionSteps / axis.steps_per_mm();
}

std::string position_rule(const char* axis, const host::AxisMachine& m) {
    return fmt::format(FMT_STRING("; the farthest an axis may go is 2^30 - 1 steps, so that every move fits the int32 "
                                  "step counts: {:.10g} mm on {} at {:.10g} steps/mm"),
                       max_position_mm(m), axis, m.steps_per_mm());
}

void check_position(const std::string& where, const char* axis, const host::AxisMachine& machine, double lo_mm,
                    double hi_mm) {
    const double limit = max_position_mm(machine);
    const double worst = std::fabs(lo_mm) > std::fabs(hi_mm) ? lo_mm : hi_mm;
    if (!(std::fabs(worst) <= limit)) {
        throw BadInput(where, fmt::format(FMT_STRING("{} {:.10g} mm is out of range"), axis, worst) +
                                  position_rule(axis, machine));
    }
}

}  // namespace

JobLimits::JobLimits(const Scenario& s, const Architecture& architecture, std::string filename)
    : m_s(s), m_architecture(architecture), m_file(std::move(filename)) {}

void JobLimits::check(const host::ProgrammedMove& m, std::size_t i, const std::vector<host::HostWait>& waits) {
    const std::string where = m_file + ":" + std::to_string(m.line);
    const geom::Box box = m.path.bounds();
    check_position(where, "X", m_s.machine.x, box.min.x_mm, box.max.x_mm);
    check_position(where, "Y", m_s.machine.y, box.min.y_mm, box.max.y_mm);
    const bool x_finer = m_s.machine.x.steps_per_mm() >= m_s.machine.y.steps_per_mm();
    const host::AxisMachine& finer = x_finer ? m_s.machine.x : m_s.machine.y;
    if (m.path.is_arc && !(m.path.radius_mm() <= max_position_mm(finer))) {
        throw BadInput(
            where, fmt::format(FMT_STRING("arc radius {:.10g} mm (I, J or R) is out of range"), m.path.radius_mm()) +
                       position_rule(x_finer ? "X" : "Y", finer));
    }
    for (; m_wait < waits.size() && waits[m_wait].before_move <= i; ++m_wait) m_job_s += waits[m_wait].seconds;
    m_job_s += m.path.length_mm() / m.feed_mm_per_min * kSecondsPerMinute;
    if (!(m_job_s <= kMaxJobS)) {
        throw BadInput(where, fmt::format(FMT_STRING("the job reaches {:.6g} s of machine time here (at its feeds, "
                                                     "with its dwells and pauses), more than the longest job "
                                                     "simulated, {:g} s (11.6 days)"),
                                          m_job_s, kMaxJobS));
    }
    m_architecture.check_move(where, m, m_s);
}

void JobLimits::finish(const std::vector<host::HostWait>& waits) {
    for (; m_wait < waits.size(); ++m_wait) {
        m_job_s += waits[m_wait].seconds;
        if (!(m_job_s <= kMaxJobS)) {
            throw BadInput(m_file + ":" + std::to_string(waits[m_wait].line),
                           fmt::format(FMT_STRING("the job reaches {:.6g} s of machine time with this wait, more than "
                                                  "the longest job simulated, {:g} s (11.6 days)"),
                                       m_job_s, kMaxJobS));
        }
    }
}

}  // namespace cnc::sim
