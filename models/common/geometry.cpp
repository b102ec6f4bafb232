#include "common/geometry.hpp"

#include <algorithm>

namespace cnc::geom {

namespace {
constexpr double kTwoPi = 6.283185307179586476925286766559;
// Coincidence tolerance for deciding that an arc is a full circle: far below one microstep (6.25 um).
constexpr double kSamePointMm = 1e-9;
}  // namespace

Segment Segment::line(Vec2 from, Vec2 to) { return Segment{from, to, false, {}, 0.0}; }

Segment Segment::arc(Vec2 from, Vec2 to, Vec2 center, bool ccw) {
    const double a0 = std::atan2(from.y_mm - center.y_mm, from.x_mm - center.x_mm);
    const double a1 = std::atan2(to.y_mm - center.y_mm, to.x_mm - center.x_mm);
    double sweep = a1 - a0;
    if (distance(from, to) <= kSamePointMm) {
        sweep = ccw ? kTwoPi : -kTwoPi;
    } else if (ccw) {
        while (sweep <= 0.0) sweep += kTwoPi;
    } else {
        while (sweep >= 0.0) sweep -= kTwoPi;
    }
    const double r = distance(from, center);
    const Vec2 end = center + Vec2{std::cos(a1) * r, std::sin(a1) * r};
    return Segment{from, end, true, center, sweep};
}

double Segment::length_mm() const {
    return is_arc ? radius_mm() * std::fabs(sweep_rad) : distance(start, end);
}

Vec2 Segment::point_at(double s_mm) const {
    const double len = length_mm();
    const double s = std::clamp(s_mm, 0.0, len);
    if (len <= 0.0) return start;
    if (!is_arc) return start + (end - start) * (s / len);
    const double a0 = std::atan2(start.y_mm - center.y_mm, start.x_mm - center.x_mm);
    const double a = a0 + sweep_rad * (s / len);
    const double r = radius_mm();
    return center + Vec2{std::cos(a) * r, std::sin(a) * r};
}

double Segment::distance_to(Vec2 p) const {
    if (!is_arc) {
        const Vec2 d = end - start;
        const double len2 = dot(d, d);
        const double u = len2 > 0.0 ? std::clamp(dot(p - start, d) / len2, 0.0, 1.0) : 0.0;
        return distance(p, start + d * u);
    }
    // On the arc if p's angle lies inside the swept range; otherwise the nearer endpoint.
    const double r = radius_mm();
    const double a0 = std::atan2(start.y_mm - center.y_mm, start.x_mm - center.x_mm);
    double ap = std::atan2(p.y_mm - center.y_mm, p.x_mm - center.x_mm) - a0;
    if (sweep_rad >= 0.0) {
        while (ap < 0.0) ap += kTwoPi;
        while (ap >= kTwoPi) ap -= kTwoPi;
        if (ap <= sweep_rad) return std::fabs(distance(p, center) - r);
    } else {
        while (ap > 0.0) ap -= kTwoPi;
        while (ap <= -kTwoPi) ap += kTwoPi;
        if (ap >= sweep_rad) return std::fabs(distance(p, center) - r);
    }
    return std::min(distance(p, start), distance(p, end));
}

}  // namespace cnc::geom
