#include "host/core/gcode.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>

#include "common/bad_input.hpp"
#include "host/core/gcode_lexer.hpp"

namespace cnc::host {

namespace {

constexpr double kMmPerInch = 25.4;
// Largest allowed difference between the start and end radius of an I/J arc, and largest shortfall of |R|
// below half the chord for an R arc. LinuxCNC's rs274ngc makes the same radius-difference check (interp_internal.hh:
// CENTER_ARC_RADIUS_TOLERANCE_MM = 0.02*sqrt(2) mm, RADIUS_TOLERANCE_MM = 0.00127 mm for R); a single 0.01 mm,
// under two microsteps of the reference machine, keeps a wrong end point from being cut silently.
constexpr double kArcToleranceMm = 0.01;
// Distance under which two machine positions are the same point (far below one 6.25 um microstep).
constexpr double kSamePointMm = 1e-9;
constexpr const char* kSupported =
    "(supported: G0 G1 G2 G3 G17 G20 G21 G90 G91 G92 G94 M2 M3 M5 M30 F I J R S N X Y)";

std::string mm_text(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.4f mm", v);
    return buf;
}

// The words of one line, grouped as RS274/NGC modal groups; at most one word per group and per letter.
struct LineWords {
    std::optional<int> motion;    // 0..3
    std::optional<int> distance;  // 90 / 91
    std::optional<int> units;     // 20 / 21
    std::optional<int> laser;     // 3 / 5
    bool set_origin = false;      // G92
    bool stop = false;            // M2 / M30
    std::optional<double> x, y, i, j, r, f;
};

[[noreturn]] void unsupported(const GcodeWord& w, const std::string& where) {
    throw BadInput(where, "unsupported word '" + w.text + "' " + kSupported);
}

// G and M numbers we know are small non-negative integers ("G01" = G1); anything else is unsupported.
int code_of(const GcodeWord& w, const std::string& where) {
    if (w.value < 0.0 || w.value > 999.0 || w.value != std::floor(w.value)) unsupported(w, where);
    return static_cast<int>(w.value);
}

void set_once(std::optional<int>& slot, int code, const GcodeWord& w, const char* group, const std::string& where) {
    if (slot) throw BadInput(where, "'" + w.text + "' conflicts with another " + group + " word on the same line");
    slot = code;
}

void set_value(std::optional<double>& slot, const GcodeWord& w, const std::string& where) {
    if (slot) throw BadInput(where, std::string("word '") + w.letter + "' appears twice on the same line");
    slot = w.value;
}

LineWords group_words(const std::vector<GcodeWord>& words, const std::string& where) {
    LineWords lw;
    for (const GcodeWord& w : words) {
        switch (w.letter) {
            case 'G': {
                const int code = code_of(w, where);
                if (code <= 3) {
                    set_once(lw.motion, code, w, "motion (G0 G1 G2 G3)", where);
                } else if (code == 20 || code == 21) {
                    set_once(lw.units, code, w, "units (G20 G21)", where);
                } else if (code == 90 || code == 91) {
                    set_once(lw.distance, code, w, "distance mode (G90 G91)", where);
                } else if (code == 92) {
                    lw.set_origin = true;
                } else if (code != 17 && code != 94) {  // seed 000 T2.1: XY plane and mm/min are the only modes
                    unsupported(w, where);
                }
                break;
            }
            case 'M': {
                const int code = code_of(w, where);
                if (code == 3 || code == 5) {
                    set_once(lw.laser, code, w, "laser (M3 M5)", where);
                } else if (code == 2 || code == 30) {
                    if (lw.stop) throw BadInput(where, "'" + w.text + "' conflicts with another program end word");
                    lw.stop = true;
                } else {
                    unsupported(w, where);
                }
                break;
            }
            case 'X': set_value(lw.x, w, where); break;
            case 'Y': set_value(lw.y, w, where); break;
            case 'I': set_value(lw.i, w, where); break;
            case 'J': set_value(lw.j, w, where); break;
            case 'R': set_value(lw.r, w, where); break;
            case 'F':
                if (w.value <= 0.0) throw BadInput(where, "feed must be > 0 ('" + w.text + "')");
                set_value(lw.f, w, where);
                break;
            case 'N':  // block number
            case 'S':  // spindle speed / laser power: the laser is on/off only (seed 000 Q8)
                break;
            default: unsupported(w, where);
        }
    }
    return lw;
}

class Interpreter {
public:
    Interpreter(std::string filename, const InterpreterOptions& opt)
        : m_opt(opt), m_pos(opt.start_mm) {
        m_program.filename = std::move(filename);
        if (!(std::isfinite(opt.rapid_feed_mm_per_min) && opt.rapid_feed_mm_per_min > 0.0)) {
            throw BadInput(m_program.filename, "rapid feed must be > 0 mm/min");
        }
    }

    // Executes one source line; returns false once the program has ended (M2/M30).
    bool execute(const std::string& text, int line) {
        m_where = m_program.filename + ":" + std::to_string(line);
        const LineWords lw = group_words(lex_gcode_line(text, m_where), m_where);
        // RS274/NGC order of execution: modes first, so G20 and G91 apply to the coordinates on their own line.
        if (lw.units) m_scale = *lw.units == 20 ? kMmPerInch : 1.0;
        if (lw.distance) m_absolute = *lw.distance == 90;
        if (lw.f) set_feed(*lw.f);
        if (lw.laser) m_laser_on = *lw.laser == 3;
        if (lw.set_origin) {
            set_origin(lw);
        } else {
            move(lw, line);
        }
        return !lw.stop;
    }

    Program take() { return std::move(m_program); }

private:
    void set_feed(double f) {
        // Stored in mm/min, so a later G20/G21 does not change the physical feed.
        m_feed_mm_per_min = f * m_scale * (m_opt.feed_unit == FeedUnit::MmPerSecond ? 60.0 : 1.0);
    }

    // G92: the current machine position gets the given program coordinates; later program coordinates are
    // shifted by the difference, while the moves stay in machine coordinates. G92 values are absolute even in G91.
    void set_origin(const LineWords& lw) {
        if (lw.motion) throw BadInput(m_where, "G92 and G" + std::to_string(*lw.motion) + " on the same line both use X/Y");
        if (!lw.x && !lw.y) throw BadInput(m_where, "G92 needs X and/or Y");
        if (lw.i || lw.j || lw.r) throw BadInput(m_where, "I, J and R are allowed only with G2/G3");
        if (lw.x) m_offset.x_mm = m_pos.x_mm - *lw.x * m_scale;
        if (lw.y) m_offset.y_mm = m_pos.y_mm - *lw.y * m_scale;
    }

    double target_axis(const std::optional<double>& word, double pos_mm, double offset_mm) const {
        if (!word) return pos_mm;
        return m_absolute ? *word * m_scale + offset_mm : pos_mm + *word * m_scale;
    }

    void move(const LineWords& lw, int line) {
        if (lw.motion) m_motion = static_cast<MotionKind>(*lw.motion);
        const bool has_axes = lw.x || lw.y;
        const bool has_arc_words = lw.i || lw.j || lw.r;
        if (!has_axes && !has_arc_words) return;
        if (!m_motion) throw BadInput(m_where, "X/Y without a motion mode: program G0, G1, G2 or G3 first");
        const MotionKind kind = *m_motion;
        const std::string g = "G" + std::to_string(static_cast<int>(kind));
        const bool is_arc = kind == MotionKind::ArcCW || kind == MotionKind::ArcCCW;
        if (!is_arc && has_arc_words) throw BadInput(m_where, "I, J and R are allowed only with G2/G3 (motion is " + g + ")");
        if (kind != MotionKind::Rapid && !m_feed_mm_per_min) {
            throw BadInput(m_where, g + " needs a feed rate but no F has been programmed");
        }
        const geom::Vec2 target{target_axis(lw.x, m_pos.x_mm, m_offset.x_mm),
                                target_axis(lw.y, m_pos.y_mm, m_offset.y_mm)};
        geom::Segment path = is_arc ? arc(lw, target, kind == MotionKind::ArcCCW, g)
                                    : geom::Segment::line(m_pos, target);
        if (path.length_mm() > kSamePointMm) {
            const double feed = kind == MotionKind::Rapid ? m_opt.rapid_feed_mm_per_min : *m_feed_mm_per_min;
            m_program.moves.push_back(ProgrammedMove{kind, path, feed, m_laser_on, line});
        }
        m_pos = target;
    }

    geom::Segment arc(const LineWords& lw, geom::Vec2 target, bool ccw, const std::string& g) const {
        if (lw.r && (lw.i || lw.j)) throw BadInput(m_where, g + " takes either I/J or R, not both");
        if (!lw.r && !lw.i && !lw.j) throw BadInput(m_where, g + " needs I/J (centre offset) or R (radius)");
        const geom::Vec2 center = lw.r ? center_from_radius(*lw.r * m_scale, target, ccw, g)
                                       : m_pos + geom::Vec2{lw.i.value_or(0.0), lw.j.value_or(0.0)} * m_scale;
        const double r_start = geom::distance(m_pos, center);
        const double r_end = geom::distance(target, center);
        if (r_start <= kSamePointMm) throw BadInput(m_where, g + " arc radius is zero (I and J are both 0)");
        if (std::fabs(r_end - r_start) > kArcToleranceMm) {
            throw BadInput(m_where, g + " end point is not on the arc: start radius " + mm_text(r_start) +
                                        ", end radius " + mm_text(r_end) + " (allowed difference " +
                                        mm_text(kArcToleranceMm) + ")");
        }
        geom::Segment path = geom::Segment::arc(m_pos, target, center, ccw);
        path.end = target;
        return path;
    }

    // R form (LinuxCNC/Fanuc): the centre lies on the perpendicular bisector of start-end; R > 0 picks the arc
    // of at most 180 degrees, R < 0 the longer one. For a short CW arc the centre is right of start->end.
    geom::Vec2 center_from_radius(double r_mm, geom::Vec2 target, bool ccw, const std::string& g) const {
        const double d = geom::distance(m_pos, target);
        if (d <= kSamePointMm) throw BadInput(m_where, g + " with R needs an end point away from the start (use I/J for a full circle)");
        if (r_mm == 0.0) throw BadInput(m_where, g + " radius R must not be 0");
        const double half = d / 2.0;
        const double r = std::fabs(r_mm);
        if (half - r > kArcToleranceMm) {
            throw BadInput(m_where, g + " radius " + mm_text(r) + " is too small for an end point " + mm_text(d) +
                                        " away (|R| must be >= " + mm_text(half) + ")");
        }
        const double h = r > half ? std::sqrt(r * r - half * half) : 0.0;
        const geom::Vec2 u = (target - m_pos) * (1.0 / d);
        const geom::Vec2 left{-u.y_mm, u.x_mm};
        const bool center_left = ccw == (r_mm > 0.0);
        return (m_pos + target) * 0.5 + left * (center_left ? h : -h);
    }

    InterpreterOptions m_opt;
    Program m_program;
    std::string m_where;
    geom::Vec2 m_pos;          // machine mm
    geom::Vec2 m_offset{};     // G92: machine = program + offset
    double m_scale = 1.0;      // mm per program unit (G21 default)
    bool m_absolute = true;    // G90 default
    bool m_laser_on = false;   // M5 until the program says M3
    std::optional<MotionKind> m_motion;
    std::optional<double> m_feed_mm_per_min;
};

}  // namespace

Program interpret(std::istream& in, const std::string& filename, const InterpreterOptions& opt) {
    Interpreter interp(filename, opt);
    std::string text;
    int line = 0;
    while (std::getline(in, text)) {
        if (!interp.execute(text, ++line)) break;
    }
    if (in.bad()) throw BadInput(filename, "read error after line " + std::to_string(line));
    return interp.take();
}

Program interpret_file(const std::string& path, const InterpreterOptions& opt) {
    std::ifstream in(path);
    if (!in) throw BadInput(path, "cannot open G-code file");
    return interpret(in, path, opt);
}

}  // namespace cnc::host
