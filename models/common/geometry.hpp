// Programmed path geometry in machine millimetres: straight lines and circular arcs in the XY plane.
// The interpreter produces it, the CAM chords it, and the metrics measure the tool against it.
#pragma once
#include <cmath>

namespace cnc::geom {

struct Vec2 {
    double x_mm = 0.0;
    double y_mm = 0.0;
};

inline Vec2 operator+(Vec2 a, Vec2 b) {
    return {a.x_mm + b.x_mm, a.y_mm + b.y_mm};
}
inline Vec2 operator-(Vec2 a, Vec2 b) {
    return {a.x_mm - b.x_mm, a.y_mm - b.y_mm};
}
inline Vec2 operator*(Vec2 a, double k) {
    return {a.x_mm * k, a.y_mm * k};
}
inline double dot(Vec2 a, Vec2 b) {
    return a.x_mm * b.x_mm + a.y_mm * b.y_mm;
}
inline double norm(Vec2 a) {
    return std::hypot(a.x_mm, a.y_mm);
}
inline double distance(Vec2 a, Vec2 b) {
    return norm(a - b);
}

// Axis-aligned bounds of a path.
struct Box {
    Vec2 min;
    Vec2 max;
};

// A line (is_arc false) or an arc about `center` from `start` to `end`; `sweep_rad` is signed
// (positive = counter-clockwise, G3) and is +-2*pi for a full circle whose start equals its end.
struct Segment {
    Vec2 start;
    Vec2 end;
    bool is_arc = false;
    Vec2 center;
    double sweep_rad = 0.0;

    static Segment line(Vec2 from, Vec2 to);
    // Arc from `from` to `to` about `center`, clockwise (G2) or counter-clockwise (G3). A `to` equal to
    // `from` gives a full circle. The radius is the start radius; `to` is projected onto it.
    static Segment arc(Vec2 from, Vec2 to, Vec2 center, bool ccw);

    [[nodiscard]] double radius_mm() const { return is_arc ? distance(start, center) : 0.0; }
    [[nodiscard]] double length_mm() const;
    // Point at path length s from the start, s clamped to [0, length].
    [[nodiscard]] Vec2 point_at(double s_mm) const;
    // Shortest distance from p to this segment (not to its infinite extension).
    [[nodiscard]] double distance_to(Vec2 p) const;
    // An arc's swept range, from its start, holds the direction `angle_rad` about the centre (atan2 convention).
    [[nodiscard]] bool sweeps_through(double angle_rad) const;
    // The smallest box holding the whole path: an arc reaches further than its ends where it crosses the
    // horizontal or vertical through its centre.
    [[nodiscard]] Box bounds() const;
};

}  // namespace cnc::geom
