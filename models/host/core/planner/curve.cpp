#include "host/core/planner/curve.hpp"

#include <algorithm>
#include <cmath>

namespace cnc::host::planner {

using geom::Vec2;

namespace {

// Shape of the spiral's curvature along the path fraction f: S(f) = 3 f^2 - 2 f^3, its integral and slopes
// (S' <= 3/2, |S''| <= 6).
double shape(double f) {
    return f * f * (3.0 - 2.0 * f);
}
double shape_integral(double f) {
    return f * f * f * (1.0 - 0.5 * f);
}
double shape_slope(double f) {
    return 6.0 * f * (1.0 - f);
}
double shape_bend(double f) {
    return 6.0 * (1.0 - 2.0 * f);
}
constexpr double kMaxShapeSlope = 1.5;
constexpr double kMaxShapeBend = 6.0;

Vec2 rotate(Vec2 v, double angle_rad) {
    const double c = std::cos(angle_rad);
    const double s = std::sin(angle_rad);
    return {c * v.x_mm - s * v.y_mm, s * v.x_mm + c * v.y_mm};
}

// An arc at path fraction f, with P(f) = centre + r(f) e(phi(f)) and r(f) phi'(f) = k (signed, |k| = length).
struct ArcState {
    Vec2 radial;  // e(phi)
    double phi;   // swept angle from the start
    double r;     // radius
    double dr;    // r'(f)
    double ddr;   // r''(f)
    double dphi;  // phi'(f)
    double k;
};

ArcState arc_state(const Curve& c, double f) {
    const double r0 = c.start_radius_mm();
    const double k0 = 1.0 / r0;
    const double dk = 1.0 / c.end_radius_mm() - k0;
    const double k = c.sweep_rad / (k0 + 0.5 * dk);
    ArcState st{};
    st.phi = k * (k0 * f + dk * shape_integral(f));
    const double kappa = k0 + dk * shape(f);
    st.r = 1.0 / kappa;
    st.dr = -dk * shape_slope(f) * st.r * st.r;
    st.ddr = -dk * (shape_bend(f) * st.r * st.r + 2.0 * shape_slope(f) * st.r * st.dr);
    st.dphi = k * kappa;
    st.k = k;
    st.radial = rotate((c.start - c.center) * k0, st.phi);
    return st;
}

}  // namespace

Curve Curve::line(Vec2 from, Vec2 to) {
    return Curve{from, to, false, {}, 0.0};
}

Curve Curve::arc(Vec2 from, Vec2 to, Vec2 center, double sweep_rad) {
    return Curve{from, to, true, center, sweep_rad};
}

Curve Curve::from_segment(const geom::Segment& segment) {
    return segment.is_arc ? arc(segment.start, segment.end, segment.center, segment.sweep_rad)
                          : line(segment.start, segment.end);
}

double Curve::length_mm() const {
    if (!is_arc) return geom::distance(start, end);
    const double r0 = start_radius_mm();
    const double r1 = end_radius_mm();
    return std::fabs(sweep_rad) * 2.0 * r0 * r1 / (r0 + r1);
}

Vec2 Curve::point_at(double s_mm) const {
    const double len = length_mm();
    if (s_mm <= 0.0 || len <= 0.0) return start;
    if (s_mm >= len) return end;
    const double f = s_mm / len;
    if (!is_arc) return start + (end - start) * f;
    // Written relative to `start` (cos(phi) - 1 = -2 sin^2(phi/2)) so that a blend arc of huge radius stays
    // exact near its ends instead of losing the digits of a far-away centre.
    const ArcState st = arc_state(*this, f);
    const double r0 = start_radius_mm();
    const Vec2 e0 = (start - center) * (1.0 / r0);
    const double h = std::sin(0.5 * st.phi);
    const Vec2 chord_dir = e0 * (-2.0 * h * h) + left_normal(e0) * std::sin(st.phi);  // rot(phi) e0 - e0
    return start + chord_dir * r0 + st.radial * (st.r - r0);
}

Vec2 Curve::first_derivative(double s_mm) const {
    const double len = length_mm();
    if (!is_arc) return (end - start) * (1.0 / len);
    const ArcState st = arc_state(*this, std::clamp(s_mm / len, 0.0, 1.0));
    return (st.radial * st.dr + left_normal(st.radial) * st.k) * (1.0 / len);
}

Vec2 Curve::second_derivative(double s_mm) const {
    if (!is_arc) return {};
    const double len = length_mm();
    const ArcState st = arc_state(*this, std::clamp(s_mm / len, 0.0, 1.0));
    // d/df of r' e + k e_perp: (r'' - k phi') e + r' phi' e_perp.
    const Vec2 d2 = st.radial * (st.ddr - st.k * st.dphi) + left_normal(st.radial) * (st.dr * st.dphi);
    return d2 * (1.0 / (len * len));
}

Vec2 Curve::unit_tangent_at(double s_mm) const {
    return unit(first_derivative(s_mm));
}

double Curve::max_stretch() const {
    if (!is_arc) return 1.0;
    const double len = length_mm();
    const double r_max = std::max(start_radius_mm(), end_radius_mm());
    const double dk = std::fabs(1.0 / end_radius_mm() - 1.0 / start_radius_mm());
    return std::hypot(kMaxShapeSlope * dk * r_max * r_max, len) / len;
}

double Curve::max_curvature_per_mm() const {
    if (!is_arc) return 0.0;
    const double len = length_mm();
    const double r_max = std::max(start_radius_mm(), end_radius_mm());
    const double dk = std::fabs(1.0 / end_radius_mm() - 1.0 / start_radius_mm());
    const double dr_max = kMaxShapeSlope * dk * r_max * r_max;
    const double ddr_max = dk * (kMaxShapeBend * r_max * r_max + 2.0 * kMaxShapeSlope * r_max * dr_max);
    const double dphi_max = len / std::min(start_radius_mm(), end_radius_mm());
    return (ddr_max + (len + dr_max) * dphi_max) / (len * len);
}

Curve Curve::cut_start(Vec2 q) const {
    if (!is_arc) return line(q, end);
    return arc(q, end, center, sweep_rad - signed_angle(start - center, q - center));
}

Curve Curve::cut_end(Vec2 q) const {
    if (!is_arc) return line(start, q);
    return arc(start, q, center, sweep_rad - signed_angle(q - center, end - center));
}

geom::Segment Curve::segment() const {
    return geom::Segment{start, end, is_arc, center, sweep_rad};
}

}  // namespace cnc::host::planner
