#include "run/moves.hpp"

#include <cmath>
#include <cstdlib>

namespace cnc::sim {

CommandedMoves::CommandedMoves(const host::MachineModel& machine, geom::Vec2 start_mm)
    : m_mm_per_step_x(machine.x.mm_per_step()), m_mm_per_step_y(machine.y.mm_per_step()), m_start_mm(start_mm) {}

metrics::MoveSpec CommandedMoves::next(const host::MotionSegment& seg, const host::ProgrammedMove* programmed_move) {
    metrics::MoveSpec m;
    m.index = seg.index;
    m.line = seg.line;
    m.from_mm = m_start_mm + geom::Vec2{static_cast<double>(m_at_x) * m_mm_per_step_x,
                                        static_cast<double>(m_at_y) * m_mm_per_step_y};
    m_at_x += seg.steps_x;
    m_at_y += seg.steps_y;
    m.to_mm = m_start_mm +
              geom::Vec2{static_cast<double>(m_at_x) * m_mm_per_step_x, static_cast<double>(m_at_y) * m_mm_per_step_y};
    const bool programmed = programmed_move != nullptr && seg.move >= 0;
    m.programmed = programmed ? seg.move : -1;
    m.path = programmed ? programmed_move->path : geom::Segment::line(m.from_mm, m.to_mm);
    m.z_end_mm = programmed ? programmed_move->z_end_mm : 0.0;
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
    return m;
}

std::vector<metrics::MoveSpec> commanded_moves(const host::Program* program,
                                               const std::vector<host::MotionSegment>& segments,
                                               const host::MachineModel& machine, geom::Vec2 start_mm) {
    CommandedMoves source(machine, start_mm);
    std::vector<metrics::MoveSpec> moves;
    moves.reserve(segments.size());
    for (const host::MotionSegment& seg : segments) {
        const bool programmed = program != nullptr && seg.move >= 0;
        moves.push_back(source.next(seg, programmed ? &program->moves[static_cast<std::size_t>(seg.move)] : nullptr));
    }
    return moves;
}

}  // namespace cnc::sim
