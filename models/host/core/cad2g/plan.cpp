#include "host/core/cad2g/plan.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <fmt/format.h>

#include "common/bad_input.hpp"
#include "common/math_constants.hpp"

namespace cnc::host::cad2g {

namespace {

constexpr std::int64_t kCountMax = 0xFFFF;  // STEPH:STEPL and STEPY:STEPVL are 16 bits (seed 003 §5.5)
// App. A4 MOV STEPL,DXL: a chord's count is 8 bits. Chords are cut for 254 steps of path, so that rounding both
// ends to the grid (half a step each) keeps every axis within 255.
constexpr double kChordStepsMax = 254.0;
// 2 pi x 2^30 / 254 rounded up: a full circle of the largest radius (machine.hpp kMaxPositionSteps).
constexpr double kMaxArcChords = 3.0e7;

struct GridPos {
    std::int64_t x = 0;
    std::int64_t y = 0;
};

CommandId command_id(MotionKind k) {
    switch (k) {
        case MotionKind::Rapid:
            return CommandId::G00;
        case MotionKind::Linear:
            return CommandId::G01;
        case MotionKind::ArcCW:
            return CommandId::G02;
        case MotionKind::ArcCCW:
            return CommandId::G03;
    }
    return CommandId::G01;
}

const char* g_name(CommandId id) {
    switch (id) {
        case CommandId::G00:
            return "G00";
        case CommandId::G01:
            return "G01";
        case CommandId::G02:
            return "G02";
        case CommandId::G03:
            return "G03";
        case CommandId::M30:
            return "M30";
    }
    return "?";
}

// Speeds outside the 8-bit range on one axis of one programmed move.
struct Clamps {
    int fast = 0;
    int slow = 0;
    double min_asked = INFINITY;
    double max_asked = 0.0;

    void add(const Ocr& o, double asked) {
        if (!o.too_fast && !o.too_slow) return;
        (o.too_fast ? fast : slow) += 1;
        min_asked = std::min(min_asked, asked);
        max_asked = std::max(max_asked, asked);
    }
};

class Planner {
public:
    Planner(const Program& program, const MachineModel& machine, const PcOptions& opt)
        : m_program(program),
          m_machine(machine),
          m_opt(opt),
          m_timer_y(y_timer(opt.variant, opt.timer)),
          m_rounding(rounding(opt.variant)) {
        m_plan.variant = opt.variant;
        m_plan.timer_x = opt.timer;
        m_plan.timer_y = m_timer_y;
    }

    Plan run() {
        if (!m_program.moves.empty()) m_cur = grid(m_program.moves.front().path.start, m_program.moves.front());
        for (std::size_t i = 0; i < m_program.moves.size(); ++i) {
            const ProgrammedMove& move = m_program.moves[i];
            std::vector<Command> cmds =
                move.path.is_arc ? arc(static_cast<int>(i), move) : line(static_cast<int>(i), move);
            clamp_warnings(move, cmds);
            for (Command& c : cmds) m_plan.commands.push_back(std::move(c));
        }
        m_plan.commands.push_back(Command{CommandId::M30, {}});
        return std::move(m_plan);
    }

private:
    // The grid point of `p`; BadInput beyond kMaxPositionSteps, where the step differences and counts below
    // would leave int64 (cncsim checks the job first: run/job_limits.hpp; this holds for direct callers).
    [[nodiscard]] GridPos grid(geom::Vec2 p, const ProgrammedMove& move) const {
        const double x = p.x_mm * m_machine.x.steps_per_mm();
        const double y = p.y_mm * m_machine.y.steps_per_mm();
        if (!(std::fabs(x) <= kMaxPositionSteps && std::fabs(y) <= kMaxPositionSteps)) {
            throw BadInput(source_line(move),
                           fmt::format(FMT_STRING("position ({:.10g}, {:.10g}) mm is beyond the {:.0f} steps an axis "
                                                  "may go from 0"),
                                       p.x_mm, p.y_mm, kMaxPositionSteps));
        }
        return {std::llround(x), std::llround(y)};
    }

    [[nodiscard]] std::uint16_t count(std::int64_t steps, bool& wrapped) const {
        const std::int64_t n = std::llabs(steps);
        wrapped = wrapped || n > kCountMax;
        return static_cast<std::uint16_t>(n & kCountMax);
    }

    // G01 and chords (eqs. 4.74-4.77): v_x = |dx| / dz v0, v_y = |dy| / dz v0, only X counted.
    [[nodiscard]] Motion feed_motion(std::int64_t sx, std::int64_t sy, const ProgrammedMove& move, bool chord) const {
        Motion m;
        m.steps_x = sx;
        m.steps_y = sy;
        m.path_feed_mm_per_min = move.feed_mm_per_min;
        const double dx_mm = static_cast<double>(sx) * m_machine.x.mm_per_step();
        const double dy_mm = static_cast<double>(sy) * m_machine.y.mm_per_step();
        const double dz_mm = std::hypot(dx_mm, dy_mm);
        const double v0 = feed_within_axis_limits(dx_mm, dy_mm, move.feed_mm_per_min, m_machine) / 60.0;
        m.speed_x_mm_per_s = std::fabs(dx_mm) / dz_mm * v0;
        m.speed_y_mm_per_s = std::fabs(dy_mm) / dz_mm * v0;
        if (sx == 0) {
            zero_dx_words(m, chord);
            m.count_x = count(sy, m.wrapped);
        } else {
            m.ocr_x = ocr_for_speed(m.speed_x_mm_per_s, m_machine.x.mm_per_step(), m_opt.timer, m_rounding);
            if (m_opt.variant != Variant::Seed) {
                // Seed 003 §5.6 improvement 2: Y follows the speed X's rounded word gives, so the ratio holds.
                const double v_x = speed_mm_per_s(m.ocr_x.value, m_machine.x.mm_per_step(), m_opt.timer);
                m.speed_y_mm_per_s = std::fabs(dy_mm) / std::fabs(dx_mm) * v_x;
            }
            m.ocr_y = ocr_for_speed(m.speed_y_mm_per_s, m_machine.y.mm_per_step(), m_timer_y, m_rounding);
            m.count_x = count(sx, m.wrapped);
        }
        m.portb = start_byte(sx, sx != 0, sy, sy != 0, true, m_opt.variant);
        return m;
    }

    // dx = 0: the seed's workaround (§5.4.2 note 1), stepx = stepy and v_x = v_y, X disabled and its timer the
    // timebase; in timer1-y a G01 counts Y's own timer instead, and a chord keeps the timebase with Y in step.
    void zero_dx_words(Motion& m, bool chord) const {
        const double s_y = m_machine.y.mm_per_step();
        if (m_opt.variant != Variant::Timer1Y) {
            m.x_timebase = true;
            m.ocr_y = ocr_for_speed(m.speed_y_mm_per_s, s_y, m_timer_y, m_rounding);
            m.ocr_x = m.ocr_y;
            return;
        }
        m.ocr_x = ocr_for_speed(m.speed_y_mm_per_s, s_y, m_opt.timer, m_rounding);
        if (!chord) {
            m.y_counted = true;
            m.ocr_y = ocr_for_speed(m.speed_y_mm_per_s, s_y, m_timer_y, m_rounding);
            return;
        }
        m.x_timebase = true;
        // One Timer0 period in Timer1 ticks: 2 N0 (OCR0A + 1) = 2 N1 (OCR1A + 1).
        m.ocr_y = ocr_for_speed(speed_mm_per_s(m.ocr_x.value, s_y, m_opt.timer), s_y, m_timer_y, m_rounding);
    }

    // G00 (eq. 4.73): both axes at v_max with one OCR (for X's microstep), both counted; timer1-y sends Y's own word.
    [[nodiscard]] Motion rapid_motion(std::int64_t sx, std::int64_t sy, const ProgrammedMove& move) const {
        Motion m;
        m.steps_x = sx;
        m.steps_y = sy;
        m.path_feed_mm_per_min = move.feed_mm_per_min;
        // One speed for both axes: the slower axis' velocity limit holds it.
        m.speed_x_mm_per_s = m.speed_y_mm_per_s =
            std::min({move.feed_mm_per_min / 60.0, m_machine.x.limits.max_velocity_mm_per_s,
                      m_machine.y.limits.max_velocity_mm_per_s});
        m.ocr_x = m.ocr_y = ocr_for_speed(m.speed_x_mm_per_s, m_machine.x.mm_per_step(), m_opt.timer, m_rounding);
        if (m_opt.variant == Variant::Timer1Y) {
            // Seed 003 §5.6 improvement 2 with the seed's equal speeds: Y at the speed X's rounded word gives.
            m.speed_y_mm_per_s = speed_mm_per_s(m.ocr_x.value, m_machine.x.mm_per_step(), m_opt.timer);
            m.ocr_y = ocr_for_speed(m.speed_y_mm_per_s, m_machine.y.mm_per_step(), m_timer_y, m_rounding);
        }
        m.count_x = count(sx, m.wrapped);
        m.count_y = count(sy, m.wrapped);
        m.portb = start_byte(sx, sx != 0, sy, sy != 0, false, m_opt.variant);
        return m;
    }

    void add(Command& c, int move_index, const ProgrammedMove& move, GridPos to, int chord) {
        const std::int64_t sx = to.x - m_cur.x;
        const std::int64_t sy = to.y - m_cur.y;
        if (sx == 0 && sy == 0) return;  // the next chord carries the remainder
        Motion m = c.id == CommandId::G00 ? rapid_motion(sx, sy, move) : feed_motion(sx, sy, move, chord >= 0);
        m.move = move_index;
        m.line = move.line;
        m.kind = move.kind;
        m.chord = chord;
        c.motions.push_back(m);
        m_cur = to;
    }

    // One command, or several when a count exceeds 16 bits and LongMoves::Split cuts it.
    std::vector<Command> line(int index, const ProgrammedMove& move) {
        const CommandId id = command_id(move.kind);
        const GridPos to = grid(move.path.end, move);
        const GridPos from = m_cur;
        const std::int64_t dx = to.x - from.x;
        const std::int64_t dy = to.y - from.y;
        const std::int64_t longest = std::max(std::llabs(dx), std::llabs(dy));
        if (longest > kCountMax) long_move_warning(move, id, longest);
        const std::int64_t pieces =
            m_opt.long_moves == LongMoves::Split ? std::max<std::int64_t>(1, (longest + kCountMax - 1) / kCountMax) : 1;
        std::vector<Command> cmds;
        for (std::int64_t i = 1; i <= pieces; ++i) {
            const double f = static_cast<double>(i) / static_cast<double>(pieces);
            const GridPos p{from.x + std::llround(static_cast<double>(dx) * f),
                            from.y + std::llround(static_cast<double>(dy) * f)};
            Command c{id, {}};
            add(c, index, move, p, -1);
            if (!c.motions.empty()) cmds.push_back(std::move(c));
        }
        return cmds;
    }

    std::vector<Command> arc(int index, const ProgrammedMove& move) {
        Command c{command_id(move.kind), {}};
        const geom::Segment& path = move.path;
        const double length_mm = path.length_mm();
        const double spm = std::max(m_machine.x.steps_per_mm(), m_machine.y.steps_per_mm());
        // A sweep within 1e-6 of a whole number of steps (end points printed to a few decimals) takes that number.
        const double by_angle = std::ceil(std::fabs(path.sweep_rad) * 180.0 / kPi / m_opt.arc_step_deg - 1e-6);
        const double by_count = std::ceil(length_mm * spm / kChordStepsMax);
        // Within the position bound an arc has at most 2 pi 2^30 / 254 chords by count; a sweep of many turns
        // (a corrupt end point) would need more than memory holds.
        const double chords_needed = std::max({1.0, by_angle, by_count});
        if (!(chords_needed <= kMaxArcChords)) {
            throw BadInput(source_line(move),
                           fmt::format(FMT_STRING("arc of {:.6g} mm needs {:.6g} chords, more than {:.0f}"), length_mm,
                                       chords_needed, kMaxArcChords));
        }
        const auto chords = static_cast<std::int64_t>(chords_needed);
        int chord = 0;
        for (std::int64_t k = 1; k <= chords; ++k) {
            const double s_mm = length_mm * static_cast<double>(k) / static_cast<double>(chords);
            const geom::Vec2 p = k == chords ? path.end : path.point_at(s_mm);
            const std::size_t before = c.motions.size();
            add(c, index, move, grid(p, move), chord);
            if (c.motions.size() == before) continue;
            ++chord;
            Motion& m = c.motions.back();
            if (m.x_timebase && c.motions.size() > 1) {
                // X is disabled, so its DIR is free: flipped, it marks where this chord starts (motion_windows).
                const std::uint8_t dir_x = 1U << LASER_ENGRAVER_PB_DIR_X;
                m.portb = static_cast<std::uint8_t>((m.portb & ~dir_x) | (~c.motions[before - 1].portb & dir_x));
            }
        }
        if (c.motions.empty()) return {};
        return {c};
    }

    std::string source_line(const ProgrammedMove& move) const {
        return m_program.filename + ":" + std::to_string(move.line);
    }

    void long_move_warning(const ProgrammedMove& move, CommandId id, std::int64_t longest) {
        const double limit_mm =
            static_cast<double>(kCountMax + 1) / std::max(m_machine.x.steps_per_mm(), m_machine.y.steps_per_mm());
        std::string text = std::string(g_name(id)) + " count " + std::to_string(longest) +
                           " exceeds the 16-bit step counter" +
                           fmt::format(FMT_STRING(" ({:.1f} mm at {:.0f} steps/mm): "), limit_mm,
                                       std::max(m_machine.x.steps_per_mm(), m_machine.y.steps_per_mm()));
        if (m_opt.long_moves == LongMoves::Split) {
            text += "sent as " + std::to_string((longest + kCountMax - 1) / kCountMax) +
                    " commands (atmega.long_moves = split)";
        } else {
            text += "sent modulo 65536 as " + std::to_string(longest & kCountMax) +
                    ", as the seed's registers take it (atmega.long_moves = wrap)";
        }
        m_plan.warnings.push_back({"long_move", source_line(move), text});
    }

    void clamp_warnings(const ProgrammedMove& move, const std::vector<Command>& cmds) {
        Clamps x;
        Clamps y;
        std::size_t motions = 0;
        for (const Command& c : cmds) {
            for (const Motion& m : c.motions) {
                if (m.steps_x != 0) x.add(m.ocr_x, m.speed_x_mm_per_s);
                if (m.steps_y != 0) y.add(m.ocr_y, m.speed_y_mm_per_s);
                ++motions;
            }
        }
        const auto report = [&](const Clamps& k, const char* kind, const char* reg, const char* axis,
                                double mm_per_step, TimerClock clk) {
            if (k.fast + k.slow == 0) return;
            const double fastest = speed_mm_per_s(0, mm_per_step, clk);
            const double slowest = speed_mm_per_s(clk.ocr_max, mm_per_step, clk);
            const std::string range = fmt::format(FMT_STRING("0..{}"), clk.ocr_max);
            m_plan.warnings.push_back(
                {kind, source_line(move),
                 std::string(g_name(command_id(move.kind))) + ": " + reg + " outside " + range + " in " +
                     std::to_string(k.fast + k.slow) + " of " + std::to_string(motions) +
                     (move.path.is_arc ? " chords (" : " commands (") + std::to_string(k.slow) + " held to " +
                     std::to_string(clk.ocr_max) + ", " + std::to_string(k.fast) + " to 0): " + axis +
                     fmt::format(FMT_STRING(" asked {:.4g}..{:.4g} mm/s, the {}-bit range is {:.4g}..{:.4g} mm/s"),
                                 k.min_asked, k.max_asked, clk.ocr_max > 0xFF ? 16 : 8, slowest, fastest)});
        };
        report(x, "ocr0a_range", "OCR0A", "X", m_machine.x.mm_per_step(), m_opt.timer);
        if (m_opt.variant == Variant::Timer1Y) {
            report(y, "ocr1a_range", "OCR1A", "Y", m_machine.y.mm_per_step(), m_timer_y);
        } else {
            report(y, "ocr2a_range", "OCR2A", "Y", m_machine.y.mm_per_step(), m_timer_y);
        }
    }

    const Program& m_program;
    const MachineModel& m_machine;
    const PcOptions& m_opt;
    const TimerClock m_timer_y;
    const OcrRounding m_rounding;
    Plan m_plan;
    GridPos m_cur;
};

}  // namespace

Plan plan_program(const Program& program, const MachineModel& machine, const PcOptions& opt) {
    validate(machine, "machine");
    if (!(std::isfinite(opt.arc_step_deg) && opt.arc_step_deg > 0.0)) {
        throw BadInput("atmega.arc_step_deg", "must be > 0");
    }
    if (!(opt.timer.f_cpu_hz > 0.0) || opt.timer.prescaler <= 0) {
        throw BadInput("atmega", "timer clock and prescaler must be > 0");
    }
    return Planner(program, machine, opt).run();
}

std::vector<Transfer> transfers(const Plan& plan) {
    std::vector<Transfer> out;
    for (std::size_t i = 0; i < plan.commands.size(); ++i) {
        const Command& c = plan.commands[i];
        const auto id = static_cast<std::uint8_t>(c.id);
        if (c.motions.empty()) {
            out.push_back({i, -1, {id}});
            continue;
        }
        for (std::size_t k = 0; k < c.motions.size(); ++k) {
            Transfer t{i, static_cast<int>(k), {}};
            if (k == 0) t.bytes.push_back(id);
            const std::vector<std::uint8_t> b = motion_bytes(c.id, c.motions[k], plan.variant);
            t.bytes.insert(t.bytes.end(), b.begin(), b.end());
            out.push_back(std::move(t));
        }
        if (c.id == CommandId::G02 || c.id == CommandId::G03)
            out.push_back({i, -1, arc_terminator(true, plan.variant)});
    }
    return out;
}

std::vector<MotionSegment> motion_segments(const Plan& plan, const MachineModel& machine) {
    std::vector<MotionSegment> segs;
    for (const Command& c : plan.commands) {
        for (const Motion& m : c.motions) {
            MotionSegment s;
            s.index = static_cast<int>(segs.size()) + 1;
            s.motion = m.kind;
            s.steps_x = m.steps_x;
            s.steps_y = m.steps_y;
            s.feed = std::llround(m.path_feed_mm_per_min);
            s.path_feed_mm_per_min = m.path_feed_mm_per_min;
            s.move = m.move;
            s.line = m.line;
            s.dx_mm = static_cast<double>(m.steps_x) * machine.x.mm_per_step();
            s.dy_mm = static_cast<double>(m.steps_y) * machine.y.mm_per_step();
            segs.push_back(s);
        }
    }
    return segs;
}

}  // namespace cnc::host::cad2g
