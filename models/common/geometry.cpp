#include "common/geometry.hpp"

#include <algorithm>

#include "common/math_constants.hpp"

namespace cnc::geom {

namespace {
// Coincidence tolerance for deciding that an arc is a full circle: far below one microstep (6.25 um).
constexpr double kSamePointMm = 1e-9;
}  // namespace

Segment Segment::line(Vec2 from, Vec2 to) {
    return Segment{from, to, false, {}, 0.0};
}

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
    if (sweeps_through(std::atan2(p.y_mm - center.y_mm, p.x_mm - center.x_mm))) {
        return std::fabs(distance(p, center) - radius_mm());
    }
    return std::min(distance(p, start), distance(p, end));
}

bool Segment::sweeps_through(double angle_rad) const {
    const double a0 = std::atan2(start.y_mm - center.y_mm, start.x_mm - center.x_mm);
    double a = angle_rad - a0;
    if (sweep_rad >= 0.0) {
        while (a < 0.0) a += kTwoPi;
        while (a >= kTwoPi) a -= kTwoPi;
        return a <= sweep_rad;
    }
    while (a > 0.0) a -= kTwoPi;
    while (a <= -kTwoPi) a += kTwoPi;
    return a >= sweep_rad;
}

Box Segment::bounds() const {
    Box b{{std::min(start.x_mm, end.x_mm), std::min(start.y_mm, end.y_mm)},
          {std::max(start.x_mm, end.x_mm), std::max(start.y_mm, end.y_mm)}};
    if (!is_arc) return b;
    struct Crossing {
        double angle_rad;
        Vec2 direction;
    };
    const Crossing crossings[] = {
        {0.0, {1.0, 0.0}}, {kTwoPi / 4, {0.0, 1.0}}, {kTwoPi / 2, {-1.0, 0.0}}, {-kTwoPi / 4, {0.0, -1.0}}};
    for (const Crossing& c : crossings) {
        if (!sweeps_through(c.angle_rad)) continue;
        const Vec2 p = center + c.direction * radius_mm();
        b.min = {std::min(b.min.x_mm, p.x_mm), std::min(b.min.y_mm, p.y_mm)};
        b.max = {std::max(b.max.x_mm, p.x_mm), std::max(b.max.y_mm, p.y_mm)};
    }
    return b;
}

}  // namespace cnc::geom
