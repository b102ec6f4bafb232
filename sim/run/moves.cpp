#include "run/moves.hpp"

#include <cmath>
#include <cstdlib>

namespace cnc::sim {

std::vector<metrics::MoveSpec> commanded_moves(const host::Program* program,
                                               const std::vector<host::MotionSegment>& segments,
                                               const host::MachineModel& machine, geom::Vec2 start_mm) {
    const double mm_x = machine.x.mm_per_step();
    const double mm_y = machine.y.mm_per_step();
    std::vector<metrics::MoveSpec> moves;
    std::int64_t at_x = 0;
    std::int64_t at_y = 0;
    for (const host::MotionSegment& seg : segments) {
        metrics::MoveSpec m;
        m.index = seg.index;
        m.line = seg.line;
        m.from_mm = start_mm + geom::Vec2{static_cast<double>(at_x) * mm_x, static_cast<double>(at_y) * mm_y};
        at_x += seg.steps_x;
        at_y += seg.steps_y;
        m.to_mm = start_mm + geom::Vec2{static_cast<double>(at_x) * mm_x, static_cast<double>(at_y) * mm_y};
        const bool programmed = program != nullptr && seg.move >= 0;
        m.programmed = programmed ? seg.move : -1;
        m.path = programmed ? program->moves[static_cast<std::size_t>(seg.move)].path
                            : geom::Segment::line(m.from_mm, m.to_mm);
        m.feed_mm_per_min = seg.path_feed_mm_per_min;
        m.rapid = seg.motion == host::MotionKind::Rapid;
        m.steps = {seg.steps_x, seg.steps_y};
        // The programmed path speed F, split over the axes in proportion to this move's own displacement.
        const double length_mm = geom::distance(m.from_mm, m.to_mm);
        const double speed_mm_per_s = m.feed_mm_per_min / 60.0;
        if (length_mm > 0.0) {
            m.rate_steps_per_s = {speed_mm_per_s * static_cast<double>(std::llabs(seg.steps_x)) / length_mm,
                                  speed_mm_per_s * static_cast<double>(std::llabs(seg.steps_y)) / length_mm};
        }
        moves.push_back(m);
    }
    return moves;
}

}  // namespace cnc::sim
