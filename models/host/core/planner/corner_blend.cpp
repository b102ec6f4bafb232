#include "host/core/planner/corner_blend.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "host/core/planner/path_limits.hpp"

namespace cnc::host::planner {

using geom::Vec2;

namespace {

// Blends shorter than this are not worth a piece: the corner becomes a stop (the planner's skip length).
constexpr double kMinBlendMm = 1e-9;
// Bisection steps on the blend radius: the bracket shrinks by 2^-60, below double resolution.
constexpr int kRadiusBisectionSteps = 60;
// The bisection's search bracket, in multiples of the two-lines radius the tangents at the corner give.
constexpr double kRadiusBracketFactor = 4.0;
// Contour-error check of an arc-side blend: samples along it, and the radius reduction per failed check.
constexpr int kContourSamples = 16;
constexpr double kRadiusShrink = 0.9;
constexpr int kMaxShrinks = 60;
// Tangency check of a constructed blend (cosine of the angle between the blend's and the curve's tangents).
constexpr double kMinTangentCos = 1.0 - 1e-9;

// One side of the corner as the planner offsets it: a line through the corner, or a circle.
struct Side {
    bool is_arc;
    Vec2 point;    // the corner
    Vec2 tangent;  // travel direction at the corner
    Vec2 center;
    double radius_mm;
    double orient;  // +1 counter-clockwise, -1 clockwise
};

Side side_at(const Curve& c, bool at_end, Vec2 corner) {
    const double s = at_end ? c.length_mm() : 0.0;
    return Side{c.is_arc,
                corner,
                c.unit_tangent_at(s),
                c.center,
                at_end ? c.end_radius_mm() : c.start_radius_mm(),
                c.sweep_rad >= 0.0 ? 1.0 : -1.0};
}

// Points where the two sides offset by `r` towards side `sigma` (+1 left) meet.
std::vector<Vec2> offset_intersections(const Side& a, const Side& b, double r, double sigma) {
    std::vector<Vec2> out;
    const auto offset_radius = [&](const Side& s) { return s.orient == sigma ? s.radius_mm - r : s.radius_mm + r; };
    if (!a.is_arc || !b.is_arc) {
        const Side& ln = a.is_arc ? b : a;
        const Side& ci = a.is_arc ? a : b;
        const double rho = offset_radius(ci);
        if (rho <= 0.0) return out;
        const Vec2 p = ln.point + left_normal(ln.tangent) * (sigma * r);
        const Vec2 pc = p - ci.center;
        const double half_b = geom::dot(ln.tangent, pc);
        const double disc = half_b * half_b - (geom::dot(pc, pc) - rho * rho);
        if (disc < 0.0) return out;
        const double root = std::sqrt(disc);
        out.push_back(p + ln.tangent * (-half_b - root));
        out.push_back(p + ln.tangent * (-half_b + root));
        return out;
    }
    const double ra = offset_radius(a);
    const double rb = offset_radius(b);
    if (ra <= 0.0 || rb <= 0.0) return out;
    const Vec2 ab = b.center - a.center;
    const double d = geom::norm(ab);
    if (d <= 0.0 || d > ra + rb || d < std::fabs(ra - rb)) return out;
    const Vec2 e = ab * (1.0 / d);
    const double x = (d * d + ra * ra - rb * rb) / (2.0 * d);
    const double h = std::sqrt(std::max(0.0, ra * ra - x * x));
    out.push_back(a.center + e * x + left_normal(e) * h);
    out.push_back(a.center + e * x - left_normal(e) * h);
    return out;
}

Vec2 foot(const Side& s, Vec2 p) {
    if (!s.is_arc) return s.point + s.tangent * geom::dot(p - s.point, s.tangent);
    return s.center + unit(p - s.center) * s.radius_mm;
}

Vec2 side_tangent(const Side& s, Vec2 q) {
    return s.is_arc ? left_normal(unit(q - s.center)) * s.orient : s.tangent;
}

// How far along `s` the point q lies from the corner (negative: beyond it): the swept angle for arcs, mm for
// lines.
double along(const Side& s, Vec2 q, bool before_corner) {
    if (!s.is_arc) return geom::dot(q - s.point, s.tangent) * (before_corner ? -1.0 : 1.0);
    const double ang =
        before_corner ? signed_angle(q - s.center, s.point - s.center) : signed_angle(s.point - s.center, q - s.center);
    return ang * s.orient;
}

// The blend with centre c, if it is tangent to both sides within their usable halves and passes
// within the tolerance of the corner.
std::optional<Curve> blend_with_centre(const Curve& a, const Curve& b, const Side& sa, const Side& sb, Vec2 c,
                                       double sigma, double tolerance_mm) {
    const Vec2 qa = foot(sa, c);
    const Vec2 qb = foot(sb, c);
    const double da = along(sa, qa, true);
    const double db = along(sb, qb, false);
    const double max_a = sa.is_arc ? 0.5 * std::fabs(a.sweep_rad) : 0.5 * a.length_mm();
    const double max_b = sb.is_arc ? 0.5 * std::fabs(b.sweep_rad) : 0.5 * b.length_mm();
    if (!(da > 0.0 && da <= max_a && db > 0.0 && db <= max_b)) return std::nullopt;
    const double sweep = signed_angle(qa - c, qb - c);
    if (sweep * sigma <= 0.0) return std::nullopt;
    const Curve blend = Curve::arc(qa, qb, c, sweep);
    if (geom::dot(blend.unit_tangent_at(0.0), side_tangent(sa, qa)) < kMinTangentCos) return std::nullopt;
    if (geom::dot(blend.unit_tangent_at(blend.length_mm()), side_tangent(sb, qb)) < kMinTangentCos) {
        return std::nullopt;
    }
    if (blend.segment().distance_to(sa.point) > tolerance_mm) return std::nullopt;
    return blend;
}

std::optional<Curve> blend_of_radius(const Curve& a, const Curve& b, const Side& sa, const Side& sb, double r,
                                     double sigma, double tolerance_mm) {
    std::optional<Curve> best;
    double best_d = 0.0;
    for (const Vec2& c : offset_intersections(sa, sb, r, sigma)) {
        const double d = geom::distance(c, sa.point);
        if (best && d >= best_d) continue;
        if (auto blend = blend_with_centre(a, b, sa, sb, c, sigma, tolerance_mm)) {
            best = blend;
            best_d = d;
        }
    }
    return best;
}

// The curve as the blend sees it: a spiral arc is taken as its circle at the corner's end, which it follows
// there (its start-radius circle could be off by the whole radius difference near the corner).
geom::Segment side_segment(const Side& s, const Curve& c) {
    if (!s.is_arc) return c.segment();
    return geom::Segment{s.center + unit(c.start - s.center) * s.radius_mm,
                         s.center + unit(c.end - s.center) * s.radius_mm, true, s.center, c.sweep_rad};
}

bool contour_within(const Curve& blend, const Curve& a, const Curve& b, const Side& sa, const Side& sb,
                    double tolerance_mm) {
    const geom::Segment seg_a = side_segment(sa, a);
    const geom::Segment seg_b = side_segment(sb, b);
    const double len = blend.length_mm();
    for (int i = 1; i < kContourSamples; ++i) {
        const Vec2 p = blend.point_at(len * i / kContourSamples);
        if (std::min(seg_a.distance_to(p), seg_b.distance_to(p)) > tolerance_mm) return false;
    }
    return true;
}

// LinuxCNC's blend radius out of the largest one (corner_blend.hpp), for a corner of half-turn `half`.
double planned_radius(double r_geom, double half, double goal_mm_per_s, double accel_mm_per_s2) {
    const double a_n = kNormalShareCircle * accel_mm_per_s2;
    const double d_geom = r_geom * std::tan(half);
    const double v_plan = std::min(std::sqrt(a_n * r_geom), goal_mm_per_s);
    const double t_blend = std::min(std::sqrt(accel_mm_per_s2 * d_geom), v_plan) / (0.5 * accel_mm_per_s2);
    const double r_blend = std::min(t_blend * v_plan / (2.0 * half), r_geom);
    return std::min(r_geom, std::max(v_plan * v_plan / a_n, r_blend));
}

}  // namespace

std::optional<Curve> corner_blend(const Curve& a, const Curve& b, double tolerance_mm, double goal_mm_per_s,
                                  double accel_mm_per_s2) {
    if (tolerance_mm <= 0.0) return std::nullopt;
    const Vec2 corner = a.end;
    const Vec2 u1 = a.unit_tangent_at(a.length_mm());
    const Vec2 u2 = b.unit_tangent_at(0.0);
    const double cr = cross(u1, u2);
    const double turn = std::atan2(std::fabs(cr), geom::dot(u1, u2));
    const double half = 0.5 * turn;
    if (cr == 0.0 || half <= 0.0) return std::nullopt;
    const double sigma = cr > 0.0 ? 1.0 : -1.0;
    // 1 - cos(h) = 2 sin^2(h/2), exact for the tiny turns of nearly tangent moves.
    const double sin_quarter = std::sin(0.5 * half);
    const double r_tol = tolerance_mm * std::cos(half) / (2.0 * sin_quarter * sin_quarter);
    const double r_len = 0.5 * std::min(a.length_mm(), b.length_mm()) / std::tan(half);
    const double r_lines = std::min(r_tol, r_len);
    std::optional<Curve> blend;
    if (!a.is_arc && !b.is_arc) {
        const double r = planned_radius(r_lines, half, goal_mm_per_s, accel_mm_per_s2);
        const double d = r * std::tan(half);
        const Vec2 qa = corner - u1 * d;
        blend = Curve::arc(qa, corner + u2 * d, qa + left_normal(u1) * (sigma * r), sigma * turn);
    } else {
        const Side sa = side_at(a, true, corner);
        const Side sb = side_at(b, false, corner);
        double lo = 0.0;
        double hi = kRadiusBracketFactor * r_lines;
        for (int i = 0; i < kRadiusBisectionSteps; ++i) {
            const double mid = 0.5 * (lo + hi);
            if (auto c = blend_of_radius(a, b, sa, sb, mid, sigma, tolerance_mm)) {
                lo = mid;
                blend = c;
            } else {
                hi = mid;
            }
        }
        for (int i = 0; blend && !contour_within(*blend, a, b, sa, sb, tolerance_mm); ++i) {
            lo *= kRadiusShrink;
            blend = i < kMaxShrinks ? blend_of_radius(a, b, sa, sb, lo, sigma, tolerance_mm) : std::nullopt;
        }
        const double r = blend ? planned_radius(lo, half, goal_mm_per_s, accel_mm_per_s2) : lo;
        if (blend && r < lo) blend = blend_of_radius(a, b, sa, sb, r, sigma, tolerance_mm);
    }
    if (!blend || blend->length_mm() < kMinBlendMm) return std::nullopt;
    return blend;
}

}  // namespace cnc::host::planner
