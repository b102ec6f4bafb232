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
    m.rapid = seg.motion == host::MotionKind::Rapid;
    m.steps = {seg.steps_x, seg.steps_y};
    set_path_feed(m, seg.path_feed_mm_per_min);
    return m;
}

void set_path_feed(metrics::MoveSpec& m, double feed_mm_per_min) {
    m.feed_mm_per_min = feed_mm_per_min;
    const double length_mm = geom::distance(m.from_mm, m.to_mm);
    if (length_mm <= 0.0) return;
    const double speed_mm_per_s = feed_mm_per_min / 60.0;
    m.rate_steps_per_s = {speed_mm_per_s * static_cast<double>(std::llabs(m.steps[0])) / length_mm,
                          speed_mm_per_s * static_cast<double>(std::llabs(m.steps[1])) / length_mm};
}

metrics::MoveSpec CommandedMoves::unstepped(const host::ProgrammedMove& programmed, int move) {
    host::MotionSegment seg;
    seg.index = 0;
    seg.motion = programmed.kind;
    seg.path_feed_mm_per_min = programmed.feed_mm_per_min;
    seg.move = move;
    seg.line = programmed.line;
    return next(seg, &programmed);  // no steps: the position stays
}

void place_unstepped(metrics::MoveSpec& m, std::optional<TimePs> next_begin_ps, TimePs last_end_ps) {
    m.t_begin_ps = next_begin_ps ? *next_begin_ps : last_end_ps + 1;
    m.t_end_ps = m.t_begin_ps;
}

std::vector<metrics::MoveSpec> commanded_moves(const host::Program* program,
                                               const std::vector<host::MotionSegment>& segments,
                                               const host::MachineModel& machine, geom::Vec2 start_mm) {
    CommandedMoves source(machine, start_mm);
    std::vector<metrics::MoveSpec> moves;
    moves.reserve(segments.size());
    int next_move = 0;  // the programmed move the next segment should belong to
    const auto unstepped_until = [&](int move) {
        for (; next_move < move; ++next_move) {
            moves.push_back(source.unstepped(program->moves[static_cast<std::size_t>(next_move)], next_move));
        }
    };
    for (const host::MotionSegment& seg : segments) {
        const bool programmed = program != nullptr && seg.move >= 0;
        if (programmed) {
            unstepped_until(seg.move);
            next_move = seg.move + 1;
        }
        moves.push_back(source.next(seg, programmed ? &program->moves[static_cast<std::size_t>(seg.move)] : nullptr));
    }
    if (program != nullptr) unstepped_until(static_cast<int>(program->moves.size()));
    return moves;
}

}  // namespace cnc::sim
