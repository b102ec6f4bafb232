// Geometry the planner follows: a line, or an arc about a fixed centre. The interpreter keeps an arc's programmed
// end point even when it lies up to its 0.01 mm tolerance off the start circle; the planner then lets the radius
// change along the arc (a spiral, as LinuxCNC's PmCircle does, there linearly) so that the tool path stays
// continuous. Here the curvature 1/r goes from 1/r0 to 1/r1 as k0 + (k1 - k0) (3 f^2 - 2 f^3) of the path
// fraction f and the swept angle grows in proportion to the curvature, so that r * dphi/ds is constant: the
// radius has slope 0 at both ends, the spiral leaves and joins exactly along the tangents of its end circles
// (a move continuing along that tangent is a tangent join, not a corner), and the path speed is exact at both
// ends (no velocity step at the joins). An arc whose end lies on the start circle is exactly that circle.
#pragma once
#include "common/geometry.hpp"

namespace cnc::host::planner {

struct Curve {
    geom::Vec2 start;
    geom::Vec2 end;
    bool is_arc = false;
    geom::Vec2 center;
    double sweep_rad = 0.0;  // signed, positive = counter-clockwise

    static Curve line(geom::Vec2 from, geom::Vec2 to);
    static Curve arc(geom::Vec2 from, geom::Vec2 to, geom::Vec2 center, double sweep_rad);
    static Curve from_segment(const geom::Segment& segment);

    [[nodiscard]] double start_radius_mm() const { return is_arc ? geom::distance(start, center) : 0.0; }
    [[nodiscard]] double end_radius_mm() const { return is_arc ? geom::distance(end, center) : 0.0; }
    // An arc's length is |sweep| times the harmonic mean of its end radii (exact on a circle; a spiral of the
    // interpreter's tolerance is longer by a relative ~(dr / (r * sweep))^2, far below any other error).
    [[nodiscard]] double length_mm() const;
    // Position at path parameter s (clamped to [0, length]); exactly `start` at 0 and `end` at length.
    [[nodiscard]] geom::Vec2 point_at(double s_mm) const;
    // dP/ds and d2P/ds2: the velocity is v * first_derivative, the acceleration a * first + v^2 * second.
    [[nodiscard]] geom::Vec2 first_derivative(double s_mm) const;
    [[nodiscard]] geom::Vec2 second_derivative(double s_mm) const;
    [[nodiscard]] geom::Vec2 unit_tangent_at(double s_mm) const;
    // Bounds over the whole curve of |dP/ds| (1 on lines and circles) and |d2P/ds2| (1/R on a circle).
    [[nodiscard]] double max_stretch() const;
    [[nodiscard]] double max_curvature_per_mm() const;
    // The same curve starting (ending) at q instead: q lies on the line, or on the arc's circle of the start
    // (end) radius; an arc keeps its centre and the radius at the other end.
    [[nodiscard]] Curve cut_start(geom::Vec2 q) const;
    [[nodiscard]] Curve cut_end(geom::Vec2 q) const;
    // As a shared geometry segment (exact for lines and circles; a spiral gets its start radius).
    [[nodiscard]] geom::Segment segment() const;
};

inline double cross(geom::Vec2 a, geom::Vec2 b) {
    return a.x_mm * b.y_mm - a.y_mm * b.x_mm;
}
// Angle turning a onto b, in (-pi, pi].
inline double signed_angle(geom::Vec2 a, geom::Vec2 b) {
    return std::atan2(cross(a, b), geom::dot(a, b));
}
inline geom::Vec2 left_normal(geom::Vec2 u) {
    return {-u.y_mm, u.x_mm};
}
inline geom::Vec2 unit(geom::Vec2 v) {
    return v * (1.0 / geom::norm(v));
}

}  // namespace cnc::host::planner
