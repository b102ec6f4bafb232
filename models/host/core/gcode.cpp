#include "host/core/gcode.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <deque>
#include <fstream>
#include <map>
#include <memory>

#include "common/bad_input.hpp"
#include "common/math_constants.hpp"
#include "host/core/cutter_comp.hpp"
#include "host/core/gcode_lexer.hpp"
#include "host/core/gcode_words.hpp"
#include "host/core/text_number.hpp"
#include "host/core/tool_table.hpp"

namespace cnc::host {

namespace {

constexpr double kMmPerInch = 25.4;
constexpr double kSecondsPerMinute = 60.0;
// Largest allowed difference between the start and end radius of an I/J arc, and largest shortfall of |R|
// below half the chord for an R arc. LinuxCNC's rs274ngc makes the same radius-difference check (interp_internal.hh:
// CENTER_ARC_RADIUS_TOLERANCE_MM = 0.02*sqrt(2) mm, RADIUS_TOLERANCE_MM = 0.00127 mm for R); a single 0.01 mm,
// under two microsteps of the reference machine, keeps a wrong end point from being cut silently.
constexpr double kArcToleranceMm = 0.01;
// Distance under which two machine positions are the same point (far below one 6.25 um microstep).
constexpr double kSamePointMm = 1e-9;
// RS274/NGC has nine work coordinate systems, G54 .. G59.3 (P1 .. P9 of G10).
constexpr std::size_t kCoordSystems = 9;
// Most turns one G2/G3 P may ask for: far beyond any helix a desktop machine cuts (a thread mill makes a few), and it
// keeps a typing error from making a job of days.
constexpr int kMaxTurns = 1000;
// Problems listed in one message before the rest are only counted.
constexpr std::size_t kMaxListedProblems = 40;
constexpr const char* kWordTable =
    "executed: G0-G3 G4 G10 L2/L20 G17 G20 G21 G28 G28.1 G30 G30.1 G53 G54-G59.3 G61 G61.1 G64 G90 G91 G90.1 "
    "G91.1 G92 G92.1-G92.3 G93 G94 M0 M1 M2 M3 M4 M5 M30 M60 F S X Y Z A E I J R P Q L N % /; ignored unless "
    "strict: T D H O M6 M7-M9 M100-M199 G40-G42 G43 G49 G80 G97 G18 G19 (with scenario.tool_table T D H M6 M61 "
    "G40-G43 G49 are executed); table: docs/gcode.md";

// X Y Z of a position or offset, machine mm.
struct Xyz {
    double x = 0.0, y = 0.0, z = 0.0;
};

// A move with the state it was programmed in, made now or held back while cutter compensation may still move
// its end (gcode.cpp's `held`).
struct MoveDraft {
    MotionKind kind;
    geom::Segment path;
    double z_from = 0.0, z_to = 0.0;
    double other_axes = 0.0;  // A/E travel, for a move of those alone
    int line = 0;
    LaserMode laser = LaserMode::Off;
    std::optional<double> power_s;
    std::optional<PathControl> path_control;
    double feed_mm_per_min = 0.0;           // F in force (a rapid: the rapid feed)
    std::optional<double> inverse_minutes;  // G93: the move's time
};

// What cutter compensation holds back, in program order: moves still open to a corner, and the waits behind them.
struct Held {
    std::optional<MoveDraft> move;
    OpenMove open;  // the move's tool-centre path
    HostWait wait{};
};

std::string mm_text(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.4f mm", v);
    return buf;
}

// Every problem of a file: the unsupported words with all their lines, and the other errors in line order.
class Problems {
public:
    explicit Problems(std::string filename) : m_file(std::move(filename)) {}

    void unsupported(const std::string& word, int line, const std::string& why) {
        auto [it, fresh] = m_words.try_emplace(word);
        if (fresh) {
            m_order.push_back(word);
            it->second.why = why;
        }
        it->second.lines.push_back(line);
    }
    void error(const std::string& message) { m_errors.push_back(message); }
    [[nodiscard]] bool any() const { return !m_order.empty() || !m_errors.empty(); }

    // One message: the first problem as "file:line: ...", each further one on a line of its own.
    [[noreturn]] void raise() const {
        std::vector<std::string> items;
        for (const std::string& w : m_order) {
            const Entry& e = m_words.at(w);
            std::string text = m_file + ":" + std::to_string(e.lines.front()) + ": " + e.why + " '" + w + "'";
            if (e.lines.size() > 1) text += " (" + lines_text(e.lines) + ")";
            items.push_back(text);
        }
        items.insert(items.end(), m_errors.begin(), m_errors.end());
        std::string msg = items.front();
        for (std::size_t k = 1; k < items.size() && k < kMaxListedProblems; ++k) msg += "\n  " + items[k];
        if (items.size() > kMaxListedProblems) {
            msg += "\n  ... and " + std::to_string(items.size() - kMaxListedProblems) + " more problems";
        }
        if (!m_order.empty()) msg += "\n  (" + std::string(kWordTable) + ")";
        throw BadInput("", msg);
    }

private:
    struct Entry {
        std::string why;
        std::vector<int> lines;
    };
    static std::string lines_text(const std::vector<int>& lines) {
        std::string t = std::to_string(lines.size()) + " lines: ";
        for (std::size_t k = 0; k < lines.size() && k < 10; ++k) t += (k ? ", " : "") + std::to_string(lines[k]);
        if (lines.size() > 10) t += ", ...";
        return t;
    }
    std::string m_file;
    std::map<std::string, Entry> m_words;
    std::vector<std::string> m_order;
    std::vector<std::string> m_errors;
};

class Interpreter {
public:
    Interpreter(std::string filename, const InterpreterOptions& opt, bool keep_moves)
        : m_opt(opt),
          m_keep_moves(keep_moves),
          m_problems(filename),
          m_tools(opt.tool_table.get()),
          m_pos(opt.start_mm),
          m_tool(opt.start_mm) {
        m_program.filename = std::move(filename);
        if (!(std::isfinite(opt.rapid_feed_mm_per_min) && opt.rapid_feed_mm_per_min > 0.0)) {
            throw BadInput(m_program.filename, "rapid feed must be > 0 mm/min");
        }
    }

    // Reads one source line; returns false once the program has ended (M2/M30, or the closing '%').
    bool line(const std::string& text, int line) {
        m_program.lines = line;
        m_line = line;
        m_where = m_program.filename + ":" + std::to_string(line);
        const std::string_view body = trim(text);
        if (body == "%") return tape_mark();
        if (!body.empty() && body.front() == '/') {
            ignore({"/", "block delete: the line is skipped (block delete switch on)"});
            return true;
        }
        try {
            const BlockWords b = group_words(lex_gcode_line(text, m_where), m_where, m_tools != nullptr);
            for (const std::string& w : b.unsupported) m_problems.unsupported(w, line, "unsupported word");
            for (const IgnoredUse& use : b.ignored) ignore(use);
            if (!b.unsupported.empty()) return true;
            return execute(b);
        } catch (const BadInput& e) {
            m_problems.error(e.what());
            return true;
        }
    }

    // The program has ended: the moves cutter compensation holds go out, then every problem of the file is
    // thrown at once.
    void finish() {
        release_held();
        if (m_problems.any()) m_problems.raise();
    }
    [[nodiscard]] const Program& program() const { return m_program; }
    [[nodiscard]] Program take() { return std::move(m_program); }
    // The moves made since the last call, in order.
    [[nodiscard]] std::deque<ProgrammedMove>& made() { return m_made; }

private:
    // LinuxCNC: a '%' line opens the program and the next one ends it (the rest of the file is not read).
    bool tape_mark() {
        ignore({"%", "tape mark: the program lies between two '%' lines"});
        return ++m_tape_marks < 2;
    }

    void ignore(const IgnoredUse& use) {
        if (m_opt.policy == GcodePolicy::Strict) {
            m_problems.unsupported(use.word, m_line,
                                   "not executed by this machine (strict policy; " + use.reason + ")");
            return;
        }
        auto it = std::find_if(m_program.ignored.begin(), m_program.ignored.end(),
                               [&](const IgnoredWord& w) { return w.word == use.word; });
        if (it == m_program.ignored.end()) {
            m_program.ignored.push_back(IgnoredWord{use.word, use.reason, {}});
            it = std::prev(m_program.ignored.end());
        }
        if (it->lines.empty() || it->lines.back() != m_line) it->lines.push_back(m_line);
    }

    // RS274/NGC order of execution (LinuxCNC's "Order of Execution" table), the parts this machine has.
    bool execute(const BlockWords& b) {
        if (b.feed_mode) m_inverse_time = *b.feed_mode == 930;
        // Units before F (unlike RS274/NGC's table), so that "F10 G20" is 10 in/min as the line reads.
        if (b.units) m_scale = *b.units == 200 ? kMmPerInch : 1.0;
        if (b.f) set_feed(*b.f);
        const bool dwell = b.non_modal == 40;
        if (b.s && !(dwell && !b.p)) m_power_s = *b.s;
        if (b.t) select_tool(*b.t);
        if (b.tool_change) change_tool(b);
        if (b.laser)
            m_laser = *b.laser == 30 ? LaserMode::Constant : *b.laser == 40 ? LaserMode::Dynamic : LaserMode::Off;
        if (dwell) do_dwell(b);
        if (b.plane) set_plane(*b.plane);
        if (b.cutter_comp) cutter_comp(b);
        if (b.tool_length) tool_length(b);
        if (b.coord_system) {
            if (m_comp.on())
                throw BadInput(m_where, "Cannot change coordinate systems with cutter radius compensation on");
            m_cs = coord_index(*b.coord_system);
        }
        if (b.path_mode) set_path_mode(b);
        if (b.distance) m_absolute = *b.distance == 900;
        if (b.arc_distance) m_arc_absolute = *b.arc_distance == 901;
        check_tool_words(b);
        if (b.non_modal && !dwell) {
            non_modal(b);
        } else if (b.tool_length == 431 && !b.motion) {
            // G43.1's axis words are the offset: the line moves only with a motion word on it (LinuxCNC).
            check_unused(b);
        } else {
            check_unused(b);
            motion(b, false);
        }
        if (b.stop) return stop(*b.stop);
        return true;
    }

    void set_feed(double f) {
        if (!(f > 0.0)) throw BadInput(m_where, "feed must be > 0 ('F" + format_double(f) + "')");
        m_f_word = f;
        // Stored in mm/min, so a later G20/G21 does not change the physical feed.
        m_feed_mm_per_min = m_opt.feed_mm_per_min.value_or(
            f * m_scale * (m_opt.feed_unit == FeedUnit::MmPerSecond ? kSecondsPerMinute : 1.0));
    }

    // G4: P in seconds (RS274/NGC and grbl); S in seconds (Marlin's seconds form) when there is no P, the spindle
    // speed beside P. G4 uses no axis words, so a motion on its line runs after the dwell (RS274/NGC's order of
    // execution: dwell before motion).
    void do_dwell(const BlockWords& b) {
        const std::optional<double> t = b.p ? b.p : b.s;
        if (!t) throw BadInput(m_where, "G4 needs P (dwell time in seconds)");
        if (!(*t >= 0.0)) throw BadInput(m_where, "G4 dwell time must be >= 0 s");
        wait(*t, WaitCause::Dwell);
    }

    void set_plane(Code10 plane) {
        if (m_comp.on() && plane != m_plane) {
            throw BadInput(m_where, "Cannot change planes with cutter radius compensation on");
        }
        m_plane = plane;
        if (plane != 170) ignore({plane == 180 ? "G18" : "G19", "plane select: arcs are cut in the XY plane only"});
    }

    static std::size_t coord_index(Code10 c) {
        static constexpr std::array<Code10, kCoordSystems> kCodes{540, 550, 560, 570, 580, 590, 591, 592, 593};
        return static_cast<std::size_t>(std::find(kCodes.begin(), kCodes.end(), c) - kCodes.begin());
    }

    void set_path_mode(const BlockWords& b) {
        if (m_comp.on()) throw BadInput(m_where, "Cannot change control mode with cutter radius compensation on");
        PathControl pc;
        pc.mode = *b.path_mode == 610   ? PathMode::ExactPath
                  : *b.path_mode == 611 ? PathMode::ExactStop
                                        : PathMode::Blend;
        if (b.p) {
            if (pc.mode != PathMode::Blend)
                throw BadInput(m_where, "P is the G64 blend tolerance: not with G61 or G61.1");
            if (!(*b.p >= 0.0)) throw BadInput(m_where, "G64 P (path tolerance) must be >= 0");
            pc.tolerance_mm = *b.p * m_scale;
        }
        m_path_control = pc;
    }

    // Words that only some codes use, left over on a line without them. An ignored code (a user M code, a coolant
    // or tool word) takes P and Q as RS274/NGC allows, and they are ignored with it.
    void check_unused(const BlockWords& b) {
        if (b.l) throw BadInput(m_where, "L is used only with G10");
        if (b.p && !b.path_mode && !b.non_modal && !arc_block(b)) {
            parameter_of_ignored_code('P', b, "G2/G3 (turns), G4, G10, G64");
        }
        if (b.q && !b.path_mode && b.tool_change != 610) parameter_of_ignored_code('Q', b, "G64, M61");
    }

    void parameter_of_ignored_code(char letter, const BlockWords& b, const std::string& users) {
        if (!b.ignored_code) {
            throw BadInput(m_where, std::string(1, letter) + " is used only with " + users +
                                        " and the codes this machine ignores (M100-M199 among them)");
        }
        ignore({std::string(1, letter), "parameter of an ignored code on the same line"});
    }

    // The motion mode this line moves in: its motion word, else the mode in force.
    std::optional<MotionKind> motion_of(const BlockWords& b) const {
        return b.motion ? std::optional(static_cast<MotionKind>(*b.motion / 10)) : m_motion;
    }

    // A G2/G3 move on this line: the motion word, or the motion mode in force with axis or arc words.
    bool arc_block(const BlockWords& b) const {
        const std::optional<MotionKind> kind = motion_of(b);
        return kind && (*kind == MotionKind::ArcCW || *kind == MotionKind::ArcCCW);
    }

    void non_modal(const BlockWords& b) {
        const Code10 c = *b.non_modal;
        refuse_with_comp(c);
        if (c == 530) return motion(b, true);
        if (b.motion) {
            throw BadInput(m_where, "G" + std::to_string(c / 10) + (c % 10 ? "." + std::to_string(c % 10) : "") +
                                        " and G" + std::to_string(*b.motion / 10) +
                                        " on the same line both use the axis words");
        }
        if (b.i || b.j || b.r) throw BadInput(m_where, "I, J and R are allowed only with G2/G3");
        switch (c) {
            case 100:
                return set_work_offset(b);
            case 280:
                return go_home(b, m_home28);
            case 300:
                return go_home(b, m_home30);
            case 281:
                m_home28 = machine_now();
                return;
            case 301:
                m_home30 = machine_now();
                return;
            case 920:
                return set_g92(b);
            case 921:
                m_g92 = m_g92_saved = Xyz{};
                return;
            case 922:
                m_g92 = Xyz{};
                return;
            case 923:
                m_g92 = m_g92_saved;
                return;
            default:
                return;
        }
    }

    // LinuxCNC refuses these while G41/G42 is in force.
    void refuse_with_comp(Code10 c) const {
        if (!m_comp.on()) return;
        // G53 only while the moves are offset (G41 with a radius above 0), as LinuxCNC's straight moves check it.
        if (c == 530 && m_comp.offsets()) throw BadInput(m_where, "Cannot use g53 with cutter radius comp");
        if (c == 280 || c == 300) throw BadInput(m_where, "Cannot use g28 or g30 with cutter radius comp");
        if (c == 281 || c == 301) {
            throw BadInput(m_where, "Cannot set reference point with cutter compensation in effect");
        }
        if (c >= 920 && c <= 923) throw BadInput(m_where, "Cannot change axis offsets with cutter radius comp");
    }

    // The programmed point (LinuxCNC's current point), machine mm: with cutter compensation the tool centre is
    // beside it.
    Xyz machine_now() const { return {m_pos.x_mm, m_pos.y_mm, m_z}; }

    // G10 L2 Pn: coordinate system n's origin in machine coordinates; L20: set so that the tool is at the given
    // coordinates in system n. P0 is the active system.
    void set_work_offset(const BlockWords& b) {
        if (!b.l || (*b.l != 2.0 && *b.l != 20.0)) throw BadInput(m_where, "G10 needs L2 or L20 (work offsets)");
        if (!b.p || *b.p < 0.0 || *b.p > static_cast<double>(kCoordSystems) || *b.p != std::floor(*b.p)) {
            throw BadInput(m_where, "G10 needs P0 .. P9 (coordinate system; 0 = the active one)");
        }
        const std::size_t n = *b.p == 0.0 ? m_cs : static_cast<std::size_t>(*b.p) - 1;
        Xyz& cs = m_cs_offset[n];
        const Xyz now = machine_now();
        const bool l20 = *b.l == 20.0;
        auto apply = [&](const std::optional<double>& w, double& off, double pos, double g92) {
            if (w) off = l20 ? pos - g92 - *w * m_scale : *w * m_scale;
        };
        apply(b.x, cs.x, now.x, m_g92.x);
        apply(b.y, cs.y, now.y, m_g92.y);
        apply(b.z, cs.z, now.z - m_tlo_mm, m_g92.z);
    }

    // G92: the tool's current position gets the given coordinates (values absolute even in G91).
    void set_g92(const BlockWords& b) {
        if (!b.x && !b.y && !b.z) throw BadInput(m_where, "G92 needs X, Y and/or Z");
        const Xyz now = machine_now();
        const Xyz& cs = m_cs_offset[m_cs];
        if (b.x) m_g92.x = now.x - cs.x - *b.x * m_scale;
        if (b.y) m_g92.y = now.y - cs.y - *b.y * m_scale;
        if (b.z) m_g92.z = now.z - m_tlo_mm - cs.z - *b.z * m_scale;
        m_g92_saved = m_g92;
    }

    // G28/G30 (LinuxCNC): with axis words, a rapid through that point (program coordinates) and then those axes
    // to the stored home; without, every axis to the home. The homes are machine 0 until G28.1/G30.1 set them.
    void go_home(const BlockWords& b, const Xyz& home) {
        const bool named = b.x || b.y || b.z;
        if (named) rapid_to(target(b, false));
        Xyz to = machine_now();
        if (!named || b.x) to.x = home.x;
        if (!named || b.y) to.y = home.y;
        if (!named || b.z) to.z = home.z;
        rapid_to(to);
    }

    void rapid_to(const Xyz& to) {
        m_arc_not_allowed = false;
        emit(MotionKind::Rapid, geom::Segment::line(m_tool, {to.x, to.y}), to.z, 0.0);
        m_pos = {to.x, to.y};
    }

    double axis_target(const std::optional<double>& word, double pos, double offset, bool machine_coords) const {
        if (!word) return pos;
        if (machine_coords) return *word * m_scale;
        return m_absolute ? *word * m_scale + offset : pos + *word * m_scale;
    }

    Xyz target(const BlockWords& b, bool machine_coords) const {
        const Xyz& cs = m_cs_offset[m_cs];
        return {axis_target(b.x, m_pos.x_mm, cs.x + m_g92.x, machine_coords),
                axis_target(b.y, m_pos.y_mm, cs.y + m_g92.y, machine_coords),
                axis_target(b.z, m_z, cs.z + m_g92.z + m_tlo_mm, machine_coords)};
    }

    void motion(const BlockWords& b, bool machine_coords) {
        m_motion = motion_of(b);
        const bool has_axes = b.x || b.y || b.z || b.a || b.e;
        const bool has_arc_words = b.i || b.j || b.r;
        if (!has_axes && !has_arc_words) return;
        if (!m_motion) throw BadInput(m_where, "axis words without a motion mode: program G0, G1, G2 or G3 first");
        const MotionKind kind = *m_motion;
        const std::string g = "G" + std::to_string(static_cast<int>(kind));
        const bool is_arc = kind == MotionKind::ArcCW || kind == MotionKind::ArcCCW;
        if (!is_arc && has_arc_words)
            throw BadInput(m_where, "I, J and R are allowed only with G2/G3 (motion is " + g + ")");
        if (machine_coords && (is_arc || m_absolute == false)) {
            throw BadInput(m_where, "G53 needs G0 or G1 in absolute mode (G90)");
        }
        if (is_arc && m_plane != 170) {
            throw BadInput(m_where, g + " in the " + (m_plane == 180 ? "G18 (XZ)" : "G19 (YZ)") +
                                        " plane: this machine cuts arcs in the XY plane (G17) only");
        }
        if (kind != MotionKind::Rapid && m_inverse_time && !b.f) {
            throw BadInput(m_where, g + " in inverse-time mode (G93) needs F on its own line");
        }
        if (kind != MotionKind::Rapid && !m_feed_mm_per_min) {
            throw BadInput(m_where, g + " needs a feed rate but no F has been programmed");
        }
        if (is_arc && m_arc_not_allowed) {
            throw BadInput(m_where,
                           "The move just after exiting cutter compensation mode must be straight, not an arc");
        }
        const Xyz to = target(b, machine_coords);
        // The programmed path, from the programmed point; without compensation the tool is there.
        const geom::Segment path =
            is_arc ? arc(b, {to.x, to.y}, kind == MotionKind::ArcCCW, g) : geom::Segment::line(m_tool, {to.x, to.y});
        const double other = std::max(b.a ? std::fabs(axis_target(b.a, m_a, 0.0, false) - m_a) : 0.0,
                                      b.e ? std::fabs(axis_target(b.e, m_e, 0.0, false) - m_e) : 0.0);
        if (m_comp.offsets()) {
            compensated(kind, path, is_arc ? (kind == MotionKind::ArcCCW ? 1 : -1) * turns(b, g) : 0, to.z, other);
        } else {
            emit(kind, path, to.z, other);
        }
        if (b.a) m_a = axis_target(b.a, m_a, 0.0, false);
        if (b.e) m_e = axis_target(b.e, m_e, 0.0, false);
        if (!is_arc) m_arc_not_allowed = false;
        m_pos = {to.x, to.y};
    }

    // A move with cutter compensation: its tool-centre path is held until the next move fixes its end; a corner
    // before it may cut the held moves short (concave) or put an arc round the programmed corner (convex).
    void compensated(MotionKind kind, const geom::Segment& programmed, int turns, double z_to, double other) {
        std::vector<OpenMove*> open;
        for (Held& h : m_held) {
            if (h.move) open.push_back(&h.open);
        }
        const OpenMove* first = open.empty() ? nullptr : open.front();
        const CompStep step =
            programmed.is_arc ? m_comp.arc(m_pos, m_tool, programmed.end, programmed.center, turns, first, m_where)
                              : m_comp.line(m_pos, m_tool, programmed.end, kind == MotionKind::Rapid, first, m_where);
        if (step.cut_open_at) cut_open_moves(open, *step.cut_open_at, m_where);
        if (step.cut_open_at || step.release_open) release_held();
        if (step.corner) {
            const MotionKind corner_kind = !step.corner->path.is_arc ? MotionKind::Rapid
                                           : step.corner->turns > 0  ? MotionKind::ArcCCW
                                                                     : MotionKind::ArcCW;
            emit(corner_kind, step.corner->path, m_z, 0.0);
        }
        const MoveDraft d = draft(kind, step.move.path, z_to, other);
        advance(d);
        m_held.push_back(Held{d, step.move, {}});
    }

    // G40 (LinuxCNC: the held moves go out as they are, and the next move, from the tool centre to the programmed
    // point, must be a straight one), G41/G42 with the tool's radius (D n: tool n; no D: the tool in the spindle),
    // G41.1/G42.1 with D the diameter.
    void cutter_comp(const BlockWords& b) {
        const Code10 c = *b.cutter_comp;
        if (c == 400) {
            if (m_comp.offsets() && !m_comp.entry()) m_arc_not_allowed = true;
            release_held();
            m_comp.turn_off();
            return;
        }
        const std::string g = c % 10 ? "G" + std::to_string(c / 10) + ".1" : "G" + std::to_string(c / 10);
        if (m_plane != 170) {
            throw BadInput(m_where, g + ": cutter radius compensation is in the XY plane (G17) only on this machine");
        }
        if (m_comp.on()) throw BadInput(m_where, "Cannot turn cutter radius comp on when on");
        double radius_mm = 0.0;
        if (c == 411 || c == 421) {
            if (!b.d) throw BadInput(m_where, g + " with no D word (the tool diameter)");
            radius_mm = *b.d * m_scale / 2.0;
        } else {
            int tool = m_loaded_tool;
            if (b.d) {
                if (*b.d != std::floor(*b.d)) throw BadInput(m_where, g + " requires D word to be a whole number");
                if (*b.d < 0.0) throw BadInput(m_where, "Negative d word tool radius index used");
                tool = tool_number(*b.d, "D");
            }
            if (tool == 0) tool = m_loaded_tool;  // D0: the tool in the spindle, as rs274 reads it
            radius_mm = tool_entry(tool).diameter_mm / 2.0;
        }
        m_comp.turn_on(c / 10 == 41 ? CompSide::Left : CompSide::Right, radius_mm, m_where);
    }

    // G43 (H n: tool n's Z offset; no H: the tool in the spindle's), G43.1 Z (the offset itself), G43.2 (adds
    // H n's offset or Z), G49 (none). The offset moves the machine Z of the next Z target (LinuxCNC: the tool tip
    // goes to the programmed Z); the offset's change itself moves nothing.
    void tool_length(const BlockWords& b) {
        if (m_comp.on()) throw BadInput(m_where, "Cannot change tool offset with cutter radius compensation on");
        const Code10 c = *b.tool_length;
        if ((c == 431 || c == 432) && (b.x || b.y || b.a || b.e)) {
            throw BadInput(m_where, std::string(c == 431 ? "G43.1" : "G43.2") +
                                        ": this machine takes a Z tool offset only (no X, Y, A or E offset)");
        }
        if (c == 490) {
            m_tlo_mm = 0.0;
        } else if (c == 430) {
            // No H, or H0: the tool in the spindle (rs274 reads H0 so).
            const int tool = b.h ? tool_number(*b.h, "H") : 0;
            m_tlo_mm = tool_entry(tool == 0 ? m_loaded_tool : tool).z_offset_mm;
        } else if (c == 431) {
            if (b.z) m_tlo_mm = *b.z * m_scale;
        } else {
            if (b.h && b.z) throw BadInput(m_where, "G43.2: Can not have both H and axis words");
            if (!b.h && !b.z) throw BadInput(m_where, "G43.2: No axes specified and H word missing");
            const int tool = b.h ? tool_number(*b.h, "H") : 0;
            m_tlo_mm += b.h ? tool_entry(tool == 0 ? m_loaded_tool : tool).z_offset_mm : *b.z * m_scale;
        }
    }

    // T n: the tool the next M6 loads (LinuxCNC selects it when T is read: it must be in the table).
    void select_tool(double t) {
        const int tool = tool_number(t, "T");
        tool_entry(tool);
        m_selected_tool = tool;
    }

    // M6 loads the selected tool; M61 Q n says tool n is in the spindle. Neither changes the length offset in
    // force: a G43 after them takes the new tool's (LinuxCNC).
    void change_tool(const BlockWords& b) {
        if (*b.tool_change == 610) {
            if (!b.q || *b.q < 0.0) {
                throw BadInput(m_where, "Need non-negative Q-word to specify tool number with M61");
            }
            const int tool = tool_number(*b.q, "M61 Q");
            tool_entry(tool);
            m_loaded_tool = tool;
            return;
        }
        if (!m_selected_tool) throw BadInput(m_where, "Need tool prepared -Txx- for toolchange");
        if (m_comp.on()) throw BadInput(m_where, "Cannot change tools with cutter radius compensation on");
        m_loaded_tool = *m_selected_tool;
    }

    // D and H belong to the codes that use them (LinuxCNC's checks).
    void check_tool_words(const BlockWords& b) const {
        if (b.d && !b.cutter_comp) throw BadInput(m_where, "D word with no G41, G41.1, G42 or G42.1 to use it");
        if (b.d && b.cutter_comp == 400) throw BadInput(m_where, "D word with no G41, G41.1, G42 or G42.1 to use it");
        if (b.h && b.tool_length != 430 && b.tool_length != 432) {
            throw BadInput(m_where, "H word with no G43 or G43.2 to use it");
        }
    }

    int tool_number(double v, const std::string& word) const {
        if (v != std::floor(v) || v < 0.0 || v > std::numeric_limits<int>::max()) {
            throw BadInput(m_where, word + " must be a whole number >= 0 (a tool number; 0: no tool)");
        }
        return static_cast<int>(v);
    }

    // The table's entry of a tool; tool 0 is no tool (diameter and length 0).
    const ToolEntry& tool_entry(int tool) const {
        if (const ToolEntry* e = m_tools->find(tool)) return *e;
        throw BadInput(m_where, "Requested tool " + std::to_string(tool) + " not found in the tool table (" +
                                    m_tools->file() + ")");
    }

    // One programmed move: the XY path goes to the architecture, the time of a Z (or A/E) component that the XY
    // hardware has no STEP pins for is kept. A move with XY and Z runs its XY path at the XY share of F, so that
    // it takes as long as the whole move at F (RS274/NGC feeds the XYZ length; A/E alone are timed at F).
    void emit(MotionKind kind, const geom::Segment& path, double z_to, double other_axes) {
        const MoveDraft d = draft(kind, path, z_to, other_axes);
        advance(d);
        output(d);
    }

    // The move with the state now in force (feed, laser, line, path control), from the current Z.
    MoveDraft draft(MotionKind kind, const geom::Segment& path, double z_to, double other_axes) const {
        const bool rapid = kind == MotionKind::Rapid;
        return MoveDraft{kind,
                         path,
                         m_z,
                         z_to,
                         other_axes,
                         m_line,
                         m_laser,
                         m_power_s,
                         m_path_control,
                         rapid ? m_opt.rapid_feed_mm_per_min : *m_feed_mm_per_min,
                         !rapid && m_inverse_time ? std::optional<double>(1.0 / *m_f_word) : std::nullopt};
    }

    // The tool centre and Z once the move is made.
    void advance(const MoveDraft& d) {
        m_tool = d.path.end;
        m_z = d.z_to;
    }

    void output(const MoveDraft& d) {
        const double xy_mm = d.path.length_mm();
        const double dz_mm = std::fabs(d.z_to - d.z_from);
        const double linear_mm = std::hypot(xy_mm, dz_mm);
        const double length_mm = linear_mm > kSamePointMm ? linear_mm : d.other_axes;
        double feed = d.feed_mm_per_min;
        if (dz_mm > 0.0) feed = std::min(feed, m_opt.z_max_feed_mm_per_min * linear_mm / dz_mm);
        const double minutes = d.inverse_minutes ? *d.inverse_minutes : length_mm / feed;
        m_program.z_travel_mm += dz_mm;
        if (xy_mm > kSamePointMm) {
            // A plain XY move keeps F exactly (the CAM's packet feed rounds it).
            const double xy_feed = dz_mm == 0.0 && !d.inverse_minutes ? feed : xy_mm / minutes;
            m_made.push_back(ProgrammedMove{d.kind, d.path, xy_feed, d.laser != LaserMode::Off, d.line, d.laser,
                                            d.power_s, d.path_control, d.z_from, d.z_to});
            if (m_keep_moves) m_program.moves.push_back(m_made.back());
            ++m_program.move_count;
        } else if (length_mm > kSamePointMm) {
            put_wait(HostWait{0, minutes * kSecondsPerMinute, WaitCause::OtherAxes, d.line});
        }
    }

    // Behind held moves a wait is held too, so that it stays between the same moves.
    void wait(double seconds, WaitCause cause) {
        if (!(seconds > 0.0)) return;
        const HostWait w{0, seconds, cause, m_line};
        if (m_held.empty()) {
            put_wait(w);
        } else {
            m_held.push_back(Held{std::nullopt, {}, w});
        }
    }

    void put_wait(HostWait w) {
        w.before_move = m_program.move_count;
        m_program.waits.push_back(w);
    }

    // The held moves (their tool-centre paths as the corners left them) and waits go out in order.
    void release_held() {
        for (Held& h : m_held) {
            if (h.move) {
                h.move->path = h.open.path;
                output(*h.move);
            } else {
                put_wait(h.wait);
            }
        }
        m_held.clear();
    }

    bool stop(Code10 code) {
        if (code == 20 || code == 300) return false;
        wait(m_opt.operator_pause_s, WaitCause::OperatorPause);
        return true;
    }

    geom::Segment arc(const BlockWords& b, geom::Vec2 target, bool ccw, const std::string& g) const {
        if (b.r && (b.i || b.j)) throw BadInput(m_where, g + " takes either I/J or R, not both");
        if (!b.r && !b.i && !b.j) throw BadInput(m_where, g + " needs I/J (centre offset) or R (radius)");
        geom::Vec2 center;
        if (b.r) {
            center = center_from_radius(*b.r * m_scale, target, ccw, g);
        } else if (m_arc_absolute) {
            const Xyz& cs = m_cs_offset[m_cs];
            center = {b.i ? *b.i * m_scale + cs.x + m_g92.x : m_pos.x_mm,
                      b.j ? *b.j * m_scale + cs.y + m_g92.y : m_pos.y_mm};
        } else {
            center = m_pos + geom::Vec2{b.i.value_or(0.0), b.j.value_or(0.0)} * m_scale;
        }
        const double r_start = geom::distance(m_pos, center);
        const double r_end = geom::distance(target, center);
        if (r_start <= kSamePointMm) throw BadInput(m_where, g + " arc radius is zero (the centre is the start point)");
        if (std::fabs(r_end - r_start) > kArcToleranceMm) {
            throw BadInput(m_where, g + " end point is not on the arc: start radius " + mm_text(r_start) +
                                        ", end radius " + mm_text(r_end) + " (allowed difference " +
                                        mm_text(kArcToleranceMm) + ")");
        }
        geom::Segment path = geom::Segment::arc(m_pos, target, center, ccw);
        path.end = target;
        path.sweep_rad += (ccw ? kTwoPi : -kTwoPi) * (turns(b, g) - 1);
        return path;
    }

    // G2/G3 P: the number of turns, the programmed arc being the last (LinuxCNC; P1 is the plain arc).
    int turns(const BlockWords& b, const std::string& g) const {
        if (!b.p) return 1;
        if (*b.p != std::floor(*b.p)) throw BadInput(m_where, g + " P (turns) must be a whole number");
        if (*b.p < 1.0 || *b.p > kMaxTurns)
            throw BadInput(m_where, g + " P (turns) must be 1 .. " + std::to_string(kMaxTurns));
        return static_cast<int>(*b.p);
    }

    // R form (LinuxCNC/Fanuc): the centre lies on the perpendicular bisector of start-end; R > 0 picks the arc
    // of at most 180 degrees, R < 0 the longer one. For a short CW arc the centre is right of start->end.
    geom::Vec2 center_from_radius(double r_mm, geom::Vec2 target, bool ccw, const std::string& g) const {
        const double d = geom::distance(m_pos, target);
        if (d <= kSamePointMm)
            throw BadInput(m_where, g + " with R needs an end point away from the start (use I/J for a full circle)");
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
    bool m_keep_moves;
    Program m_program;
    std::deque<ProgrammedMove> m_made;
    Problems m_problems;
    std::string m_where;
    int m_line = 0;
    int m_tape_marks = 0;
    const ToolTable* m_tools;  // none: the tool words are ignored
    geom::Vec2 m_pos;          // the programmed point, machine mm
    geom::Vec2 m_tool;         // the tool centre, machine mm: beside m_pos under G41/G42
    double m_z = 0.0;          // machine mm (with the tool length offset)
    CutterComp m_comp;
    std::deque<Held> m_held;                       // moves and waits cutter compensation holds back
    bool m_arc_not_allowed = false;                // the move after a G40 must be straight (LinuxCNC)
    std::optional<int> m_selected_tool;            // T
    int m_loaded_tool = 0;                         // M6 / M61; 0: none
    double m_tlo_mm = 0.0;                         // tool length offset in force (G43), machine mm
    double m_a = 0.0, m_e = 0.0;                   // program units of the A and E axes
    std::array<Xyz, kCoordSystems> m_cs_offset{};  // G54 .. G59.3 origins, machine mm
    std::size_t m_cs = 0;                          // G54
    Xyz m_g92{}, m_g92_saved{};
    Xyz m_home28{}, m_home30{};          // G28/G30 homes: machine 0 until G28.1/G30.1
    double m_scale = 1.0;                // mm per program unit (G21 default)
    bool m_absolute = true;              // G90 default
    bool m_arc_absolute = false;         // G91.1 default: I/J relative to the start
    bool m_inverse_time = false;         // G94 default
    Code10 m_plane = 170;                // G17
    LaserMode m_laser = LaserMode::Off;  // M5 until the program says M3/M4
    std::optional<double> m_power_s;
    std::optional<PathControl> m_path_control;
    std::optional<MotionKind> m_motion;
    std::optional<double> m_feed_mm_per_min;
    std::optional<double> m_f_word;  // F as written (G93: 1 / minutes)
};

}  // namespace

const char* to_string(WaitCause cause) {
    switch (cause) {
        case WaitCause::Dwell:
            return "dwell";
        case WaitCause::OperatorPause:
            return "operator_pause";
        case WaitCause::OtherAxes:
            return "z_moves";
    }
    return "?";
}

double Program::wait_s(WaitCause cause) const {
    double s = 0.0;
    for (const HostWait& w : waits) {
        if (w.cause == cause) s += w.seconds;
    }
    return s;
}

double Program::wait_s_between(std::size_t first, std::size_t last) const {
    double s = 0.0;
    for (const HostWait& w : waits) {
        if (w.before_move >= first && w.before_move < last) s += w.seconds;
    }
    return s;
}

// Lines end in LF, with any CRs before it (CR LF, and the CR CR LF some CAM exports write): one line end each. A file
// with no LF at all (classic Mac) ends its lines in CR; in a file with LF, a CR elsewhere is blank space, as
// LinuxCNC's rs274 reads it. A UTF-8 byte-order mark at the start is skipped.
class GcodeStream::LineReader {
public:
    LineReader(std::istream& in, std::string filename)
        : m_in(in), m_file(std::move(filename)), m_cr_ends_line(!has_line_feed(in)) {}

    // The next line without its ending; false at the end of the text.
    bool read(std::string& line) {
        line.clear();
        std::streambuf& buf = *m_in.rdbuf();
        bool ended = false;
        for (int c = buf.sbumpc(); c != std::char_traits<char>::eof(); c = buf.sbumpc()) {
            if (c == '\n' || (c == '\r' && m_cr_ends_line)) {
                ended = true;
                break;
            }
            line.push_back(c == '\r' ? ' ' : static_cast<char>(c));
        }
        if (m_in.bad()) throw BadInput(m_file, "read error");
        if (m_first && line.rfind(kByteOrderMark, 0) == 0)
            line.erase(0, std::char_traits<char>::length(kByteOrderMark));
        m_first = false;
        return ended || !line.empty();
    }

private:
    // Looks ahead for an LF and goes back to where the text starts. A stream that cannot go back (a pipe) is
    // taken to end its lines in LF: CR-only text is then one line.
    static bool has_line_feed(std::istream& in) {
        const std::istream::pos_type start = in.tellg();
        if (start == std::istream::pos_type(-1)) return true;
        std::streambuf& buf = *in.rdbuf();
        bool found = false;
        for (int c = buf.sbumpc(); c != std::char_traits<char>::eof(); c = buf.sbumpc()) {
            if (c == '\n') {
                found = true;
                break;
            }
        }
        in.clear();
        in.seekg(start);
        return found;
    }

    static constexpr const char* kByteOrderMark = "\xEF\xBB\xBF";
    std::istream& m_in;
    std::string m_file;
    bool m_cr_ends_line;
    bool m_first = true;
};

struct GcodeStream::State {
    State(std::istream& in, const std::string& filename, const InterpreterOptions& opt, bool keep_moves)
        : lines(in, filename), interp(filename, opt, keep_moves) {}
    LineReader lines;
    Interpreter interp;
    std::string text;
    int line = 0;
    bool ended = false;
};

GcodeStream::GcodeStream(std::istream& in, const std::string& filename, const InterpreterOptions& opt, bool keep_moves)
    : m_state(std::make_unique<State>(in, filename, opt, keep_moves)) {}

GcodeStream::GcodeStream(const std::string& path, const InterpreterOptions& opt, bool keep_moves)
    : m_file(std::make_unique<std::ifstream>(path, std::ios::binary)) {
    if (!*m_file) throw BadInput(path, "cannot open G-code file");
    m_state = std::make_unique<State>(*m_file, path, opt, keep_moves);
}

GcodeStream::~GcodeStream() = default;

std::optional<ProgrammedMove> GcodeStream::next() {
    State& st = *m_state;
    std::deque<ProgrammedMove>& made = st.interp.made();
    while (made.empty() && !st.ended) {
        st.ended = !st.lines.read(st.text) || !st.interp.line(st.text, ++st.line);
        if (st.ended) st.interp.finish();
    }
    if (made.empty()) return std::nullopt;
    ProgrammedMove move = made.front();
    made.pop_front();
    return move;
}

const Program& GcodeStream::program() const {
    return m_state->interp.program();
}

Program GcodeStream::take() {
    return m_state->interp.take();
}

Program interpret(std::istream& in, const std::string& filename, const InterpreterOptions& opt) {
    GcodeStream stream(in, filename, opt, true);
    while (stream.next()) {
    }
    return stream.take();
}

Program interpret_file(const std::string& path, const InterpreterOptions& opt) {
    GcodeStream stream(path, opt, true);
    while (stream.next()) {
    }
    return stream.take();
}

}  // namespace cnc::host
