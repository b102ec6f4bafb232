#include "host/core/cutter_comp.hpp"

#include <cmath>

#include "common/bad_input.hpp"
#include "common/math_constants.hpp"

namespace cnc::host {

namespace {

constexpr double kHalfPi = kPi / 2.0;
// LinuxCNC's corner tolerance (TOLERANCE_CONCAVE_CORNER, radians): corners within it of straight on need no arc,
// and a concave corner is one turning back by more than it.
constexpr double kCornerRad = 0.05;
// LinuxCNC's equality tolerance for the entry arc's construction (TOLERANCE_EQUAL).
constexpr double kEqual = 1e-6;
// How much longer a corner may make an open arc before LinuxCNC calls it a gouge: its 0.001 inch (0.0254 in a
// millimetre program), compared with the sweep in radians as its interpreter does.
constexpr double kArcLengthenRad = 0.0254;

constexpr const char* kToolTooBig = "Tool radius not less than arc radius with comp";
constexpr const char* kArcGouge = "Arc move in concave corner cannot be reached by the tool without gouging";

geom::Vec2 unit(double angle_rad) {
    return {std::cos(angle_rad), std::sin(angle_rad)};
}

double angle_of(geom::Vec2 v) {
    return std::atan2(v.y_mm, v.x_mm);
}

geom::Segment arc_path(geom::Vec2 from, geom::Vec2 to, geom::Vec2 center, int turns) {
    geom::Segment s;
    s.start = from;
    s.end = to;
    s.is_arc = true;
    s.center = center;
    s.sweep_rad = sweep_rad(from, center, turns, to);
    return s;
}

OpenMove open_arc(geom::Vec2 from, geom::Vec2 to, geom::Vec2 center, int turns, double planned_sweep_rad) {
    OpenMove m;
    m.path = arc_path(from, to, center, turns);
    m.turns = turns;
    m.planned_sweep_rad = planned_sweep_rad;
    return m;
}

OpenMove open_line(geom::Vec2 from, geom::Vec2 to, geom::Vec2 direction, bool rapid) {
    OpenMove m;
    m.path = geom::Segment::line(from, to);
    m.direction = direction;
    m.rapid = rapid;
    return m;
}

}  // namespace

double sweep_rad(geom::Vec2 from, geom::Vec2 center, int turns, geom::Vec2 to) {
    if (turns == 0) return 0.0;
    const double a = angle_of(from - center);
    const double b = angle_of(to - center);
    const double whole = kTwoPi * (std::abs(turns) - 1);
    if (turns > 0) return (b > a ? b - a : b - a + kTwoPi) + whole;
    return -((a > b ? a - b : a - b + kTwoPi) + whole);
}

void CutterComp::turn_on(CompSide side, double radius_mm, const std::string& where) {
    if (m_on) throw BadInput(where, "Cannot turn cutter radius comp on when on");
    if (radius_mm < 0.0) {
        side = side == CompSide::Left ? CompSide::Right : CompSide::Left;
        radius_mm = -radius_mm;
    }
    m_on = true;
    m_entry = true;
    m_side = side;
    m_radius_mm = radius_mm;
}

// The entry (LinuxCNC's first compensated straight move): from where the tool is to one radius beside the
// programmed end, square to the programmed move. The programmed move must be longer than the radius.
CompStep CutterComp::entry_line(geom::Vec2 from, geom::Vec2 tool, geom::Vec2 to, bool rapid,
                                const std::string& where) const {
    if (geom::distance(from, to) <= m_radius_mm) {
        throw BadInput(where, "Length of cutter compensation entry move is not greater than the tool radius");
    }
    const geom::Vec2 normal = unit(angle_of(to - from) + side_sign() * kHalfPi);
    CompStep step;
    step.release_open = true;
    // LinuxCNC records the offset direction as this move's direction for a later concave corner's check.
    step.move = open_line(tool, to + normal * m_radius_mm, normal, rapid);
    return step;
}

// An entry arc (LinuxCNC's first compensated arc): the programmed arc moved to end one radius beside its end, with
// its centre moved along the programmed centre's direction so that it still starts where the tool is.
CompStep CutterComp::entry_arc(geom::Vec2 from, geom::Vec2 tool, geom::Vec2 to, geom::Vec2 center, int turns,
                               const std::string& where) const {
    const double r = m_radius_mm;
    if (geom::distance(from, to) <= r) {
        throw BadInput(where, "Radius of cutter compensation entry arc is not greater than the tool radius");
    }
    if (inside(turns) && geom::distance(center, from) <= r) throw BadInput(where, kToolTooBig);
    const geom::Vec2 end = to + unit(inside(turns) ? angle_of(center - to) : angle_of(to - center)) * r;
    // The new centre lies on the line from `end` toward the programmed centre, as far from `end` as from `from`.
    const double toward_center = angle_of(center - end);
    const double apex = angle_of(from - end) - toward_center;
    if (std::fabs(std::cos(apex)) < kEqual) throw BadInput(where, kToolTooBig);
    const double reach = geom::distance(from, end) / 2.0 / std::cos(apex);
    const geom::Vec2 new_center = end + unit(toward_center) * reach;
    CompStep step;
    step.release_open = true;
    step.move = open_arc(tool, end, new_center, turns, sweep_rad(from, new_center, turns, end));
    return step;
}

// The arc round a convex corner: about the programmed corner, one radius out, clockwise for G41.
OpenMove CutterComp::corner_arc(geom::Vec2 from, geom::Vec2 to, geom::Vec2 corner) const {
    return open_arc(from, to, corner, m_side == CompSide::Left ? -1 : 1, 0.0);
}

CompStep CutterComp::line(geom::Vec2 from, geom::Vec2 tool, geom::Vec2 to, bool rapid, const OpenMove* open,
                          const std::string& where) {
    if (m_entry) {
        CompStep step = entry_line(from, tool, to, rapid, where);
        m_entry = false;
        return step;
    }
    CompStep step;
    if (from.x_mm == to.x_mm && from.y_mm == to.y_mm) {
        // No XY motion (a Z move): it waits behind the open moves and ends where they end.
        step.move = open_line(tool, tool, {}, rapid);
        return step;
    }
    const double r = m_radius_mm;
    // theta: from the programmed corner to the tool centre (square to the last move); alpha: the new move. beta:
    // how far the path turns away from the tool's side at the corner, less 90 degrees (0: straight on).
    double theta = angle_of(tool - from);
    double alpha = angle_of(to - from);
    double beta = 0.0;
    double gamma = 0.0;
    if (m_side == CompSide::Left) {
        if (theta < alpha) theta += kTwoPi;
        beta = theta - alpha - kHalfPi;
        gamma = kHalfPi;
    } else {
        if (alpha < theta) alpha += kTwoPi;
        beta = alpha - theta - kHalfPi;
        gamma = -kHalfPi;
    }
    const geom::Vec2 offset = unit(alpha + gamma) * r;
    const geom::Vec2 end = to + offset;
    const bool after_arc = open != nullptr && open->path.is_arc;
    // LinuxCNC also takes a turn of 180 degrees off the outside of an arc as concave (a line leaving the top of an
    // "h" shape's round part along its stem): the tool stays above and beside, not round the loop.
    const bool concave =
        beta < -kCornerRad || beta > kPi + kCornerRad || (beta > kPi - kCornerRad && after_arc && !inside(open->turns));
    geom::Vec2 start = tool;
    if (concave && open != nullptr) {
        if (!after_arc) {
            // Back along the last line until the new line's offset crosses it.
            const double half_corner = (beta + kPi) / 2.0;
            if (half_corner == 0.0)
                throw BadInput(where, "Zero degree inside corner is invalid for cutter compensation");
            start = tool + unit(theta + gamma) * (r / std::tan(half_corner));
        } else {
            // Back along the last arc (its tool-centre circle) to where it meets the new line's offset.
            const OpenMove& prev = *open;
            const double old_r = geom::distance(prev.path.end, prev.path.center);
            const double normal = prev.turns > 0 ? alpha + kHalfPi : alpha - kHalfPi;
            const double programmed_r = inside(prev.turns) ? old_r + r : old_r - r;
            const double to_line = programmed_r * std::cos(normal - angle_of(prev.path.center - from));
            const double l = (inside(prev.turns) ? to_line - r : to_line + r) / old_r;
            if (l > 1.0 || l < -1.0) {
                throw BadInput(
                    where, "Arc to straight motion makes a corner the compensated tool can't fit in without gouging");
            }
            const double back = inside(prev.turns) == (prev.turns > 0) ? -std::acos(l) : std::acos(l);
            start = prev.path.center + unit(normal + kPi + back) * old_r;
        }
        step.cut_open_at = start;
    } else if (!concave && beta > kCornerRad) {
        // Convex: round the corner on the tool radius (a rapid has no arc: a line to the same point).
        step.release_open = true;
        const geom::Vec2 mid = from + offset;
        step.corner = rapid ? open_line(tool, mid, {}, true) : corner_arc(tool, mid, from);
        start = mid;
    } else {
        step.release_open = true;
    }
    step.move = open_line(start, end, to - from, rapid);
    return step;
}

CompStep CutterComp::arc(geom::Vec2 from, geom::Vec2 tool, geom::Vec2 to, geom::Vec2 center, int turns,
                         const OpenMove* open, const std::string& where) {
    if (m_entry) {
        CompStep step = entry_arc(from, tool, to, center, turns, where);
        m_entry = false;
        return step;
    }
    const double r = m_radius_mm;
    const double arc_r = geom::distance(center, to);
    // theta: the last move's direction at the corner; alpha: the arc's tangent at its start; beta as for lines.
    const double theta = angle_of(tool - from) + (m_side == CompSide::Left ? -kHalfPi : kHalfPi);
    double delta = angle_of(center - from);
    const double alpha = turns > 0 ? delta - kHalfPi : delta + kHalfPi;
    double beta = m_side == CompSide::Left ? theta - alpha : alpha - theta;
    if (beta > 1.5 * kPi) {
        beta -= kTwoPi;
    } else if (beta < -kHalfPi) {
        beta += kTwoPi;
    }
    const bool in = inside(turns);
    if (in && arc_r <= r) throw BadInput(where, kToolTooBig);
    if (!in) delta += kPi;  // `delta`: from the programmed start to the tool centre's start on this arc
    const geom::Vec2 end = to + unit(in ? angle_of(center - to) : angle_of(to - center)) * r;
    const bool after_arc = open != nullptr && open->path.is_arc;
    const bool concave = beta < -kCornerRad || beta > kPi + kCornerRad || (std::fabs(beta - kPi) < kCornerRad && !in);
    geom::Vec2 start = tool;
    if (concave && open != nullptr) {
        if (!after_arc) {
            // Back along the last line to where it meets this arc's tool-centre circle.
            const double across = arc_r * std::sin(beta - kHalfPi);
            const double circle_r = in ? arc_r - r : arc_r + r;
            const double l = (in ? across + r : across - r) / circle_r;
            if (l > 1.0 || l < -1.0) throw BadInput(where, kArcGouge);
            const double at = in ? theta + (turns > 0 ? std::asin(l) : -std::asin(l))
                                 : theta + kPi + (turns > 0 ? -std::asin(l) : std::asin(l));
            start = center + unit(at) * circle_r;
        } else {
            // Where the last arc's tool-centre circle meets this one's.
            const OpenMove& prev = *open;
            const double old_r = geom::distance(prev.path.end, prev.path.center);
            const double new_r = in ? arc_r - r : arc_r + r;
            const double between = geom::distance(prev.path.center, center);
            if (old_r == 0.0 || between == 0.0) {
                throw BadInput(where, "Arc to arc motion is invalid because the arcs have the same center");
            }
            const double c = (old_r * old_r + between * between - new_r * new_r) / (2.0 * old_r * between);
            if (c > 1.0 || c < -1.0) {
                throw BadInput(where,
                               "Arc to arc motion makes a corner the compensated tool can't fit in without gouging");
            }
            const double pull = inside(prev.turns) == (turns > 0) ? std::acos(c) : -std::acos(c);
            start = prev.path.center + unit(angle_of(center - prev.path.center) + pull) * old_r;
        }
        CompStep step;
        step.cut_open_at = start;
        step.move = open_arc(start, end, center, turns, sweep_rad(from, center, turns, to));
        return step;
    }
    CompStep step;
    step.release_open = true;
    if (!concave && beta > kCornerRad) {
        const geom::Vec2 mid = from + unit(delta) * r;
        step.corner = corner_arc(tool, mid, from);
        start = mid;
    }
    step.move = open_arc(start, end, center, turns, sweep_rad(from, center, turns, to));
    return step;
}

void cut_open_moves(std::vector<OpenMove*>& open, geom::Vec2 to, const std::string& where) {
    if (open.empty()) return;
    const geom::Vec2 start = open.front()->path.start;
    for (const OpenMove* m : open) {
        if (m->path.is_arc) {
            const double sweep = sweep_rad(start, m->path.center, m->turns, to);
            if (m->planned_sweep_rad != 0.0 && std::fabs(sweep) > std::fabs(m->planned_sweep_rad) + kArcLengthenRad) {
                throw BadInput(where, kArcGouge);
            }
        } else if (geom::dot(m->direction, to - start) < 0.0) {
            // The corner lies behind the line's start: the path crosses itself.
            throw BadInput(where, m->rapid ? "Straight traverse in concave corner cannot be reached by the tool "
                                             "without gouging"
                                           : "Straight feed in concave corner cannot be reached by the tool without "
                                             "gouging");
        }
    }
    for (OpenMove* m : open) {
        if (m != open.front()) m->path.start = to;
        m->path.end = to;
        if (m->path.is_arc) m->path.sweep_rad = sweep_rad(m->path.start, m->path.center, m->turns, to);
    }
}

}  // namespace cnc::host
