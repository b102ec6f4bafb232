#include "run/held_feeds.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <utility>
#include <vector>

namespace cnc::sim {

namespace {

constexpr double kPi = 3.14159265358979323846;
// A feed held by less than this (relative) is the rounding of a limit typed as a decimal, not a held feed.
constexpr double kRelativeTolerance = 1e-9;

// The feed along the direction (ux, uy) within both axis limits, and the axis that holds it.
HeldFeed held_along(double ux, double uy, double feed_mm_per_min, const host::MachineModel& machine) {
    const double held = host::feed_within_axis_limits(ux, uy, feed_mm_per_min, machine);
    if (!(held < feed_mm_per_min * (1.0 - kRelativeTolerance))) return {feed_mm_per_min, 0};
    // The axis that would use the larger share of its limit at F is the one at its limit at the held feed.
    const bool x = std::fabs(ux) / machine.x.limits.max_velocity_mm_per_s >=
                   std::fabs(uy) / machine.y.limits.max_velocity_mm_per_s;
    return {held, x ? 'x' : 'y'};
}

// The directions an arc's tangent takes at its ends and where it crosses an axis through its centre: the
// tangent runs most along X where the radius is along Y, and the other way round.
std::vector<double> arc_angles(const geom::Segment& arc) {
    std::vector<double> angles = {std::atan2(arc.start.y_mm - arc.center.y_mm, arc.start.x_mm - arc.center.x_mm),
                                  std::atan2(arc.end.y_mm - arc.center.y_mm, arc.end.x_mm - arc.center.x_mm)};
    for (const double a : {0.0, kPi / 2.0, kPi, -kPi / 2.0}) {
        if (arc.sweeps_through(a)) angles.push_back(a);
    }
    return angles;
}

std::string mm_per_min(double v) {
    std::ostringstream t;
    t << std::fixed << std::setprecision(1) << v << " mm/min";
    return t.str();
}

}  // namespace

HeldFeed held_feed(const host::ProgrammedMove& m, const host::MachineModel& machine) {
    const double f = m.feed_mm_per_min;
    if (m.kind == host::MotionKind::Rapid || !(m.path.length_mm() > 0.0)) return {f, 0};
    if (!m.path.is_arc)
        return held_along(m.path.end.x_mm - m.path.start.x_mm, m.path.end.y_mm - m.path.start.y_mm, f, machine);
    HeldFeed lowest{f, 0};
    for (const double a : arc_angles(m.path)) {
        const HeldFeed h = held_along(-std::sin(a), std::cos(a), f, machine);
        if (h.feed_mm_per_min < lowest.feed_mm_per_min) lowest = h;
    }
    return lowest;
}

HeldFeedWarnings::HeldFeedWarnings(const host::MachineModel& machine, std::string filename)
    : m_machine(machine), m_file(std::move(filename)) {}

void HeldFeedWarnings::add(const host::ProgrammedMove& m) {
    const HeldFeed h = held_feed(m, m_machine);
    if (h.axis == 0) {
        close();
        return;
    }
    if (!(m_open && m_open->asked_mm_per_min == m.feed_mm_per_min &&
          m_open->held.feed_mm_per_min == h.feed_mm_per_min)) {
        close();
        m_open = Held{m.line, m.line, m.feed_mm_per_min, h};
    }
    m_open->last_line = m.line;
    (h.axis == 'x' ? m_open->by_x : m_open->by_y) = true;
}

void HeldFeedWarnings::close() {
    if (!m_open) return;
    const Held& h = *m_open;
    std::ostringstream where, text;
    where << m_file << ':' << h.first_line;
    if (h.last_line != h.first_line) where << '-' << h.last_line;
    text << "feed " << mm_per_min(h.asked_mm_per_min) << " held to " << mm_per_min(h.held.feed_mm_per_min) << " by ";
    if (h.by_x) text << "machine.x.max_velocity_mm_per_s = " << m_machine.x.limits.max_velocity_mm_per_s;
    if (h.by_x && h.by_y) text << " and ";
    if (h.by_y) text << "machine.y.max_velocity_mm_per_s = " << m_machine.y.limits.max_velocity_mm_per_s;
    text << ": every architecture holds a move to its axes' velocity limits, so it runs slower than asked (its feed "
            "error is against the F asked)";
    m_done.push_back({"feed_held", where.str(), text.str()});
    m_open.reset();
}

void HeldFeedWarnings::finish(std::vector<Warning>& out) {
    close();
    out.insert(out.end(), m_done.begin(), m_done.end());
    m_done.clear();
}

}  // namespace cnc::sim
