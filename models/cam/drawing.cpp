#include "cam/drawing.hpp"

#include <cmath>

namespace cnc::cam {

geom::Segment reversed(const geom::Segment& s) {
    if (!s.is_arc) return geom::Segment::line(s.end, s.start);
    return geom::Segment::arc(s.end, s.start, s.center, s.sweep_rad < 0.0);
}

geom::Segment bulge_segment(geom::Vec2 from, geom::Vec2 to, double bulge) {
    const geom::Vec2 chord = to - from;
    const double c = geom::norm(chord);
    if (bulge == 0.0 || c == 0.0) return geom::Segment::line(from, to);
    // The centre lies on the chord's perpendicular bisector, (1 - b^2) / (4 b) chord lengths from its midpoint, on
    // the left of the chord for a counter-clockwise arc of up to half a turn (b <= 1).
    const geom::Vec2 left{-chord.y_mm, chord.x_mm};
    const geom::Vec2 centre = (from + to) * 0.5 + left * ((1.0 - bulge * bulge) / (4.0 * bulge));
    return geom::Segment::arc(from, to, centre, bulge > 0.0);
}

}  // namespace cnc::cam
