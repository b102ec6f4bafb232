#include "host/core/gcode_words.hpp"

#include <cmath>

#include "common/bad_input.hpp"

namespace cnc::host {

namespace {

constexpr const char* kNoToolTable = "no tool table: tool radius and length are 0";

// G and M numbers are small non-negative codes with at most one decimal ("G01" = G1, "G61.1").
std::optional<Code10> code_of(const GcodeWord& w) {
    const double tenths = w.value * 10.0;
    if (!(w.value >= 0.0 && w.value <= 999.9) || std::fabs(tenths - std::round(tenths)) > 1e-6) return std::nullopt;
    return static_cast<Code10>(std::lround(tenths));
}

void set_once(std::optional<Code10>& slot, Code10 code, const GcodeWord& w, const char* group,
              const std::string& where) {
    if (slot) throw BadInput(where, "'" + w.text + "' conflicts with another " + group + " word on the same line");
    slot = code;
}

void set_value(std::optional<double>& slot, const GcodeWord& w, const std::string& where) {
    if (slot) throw BadInput(where, std::string("word '") + w.letter + "' appears twice on the same line");
    slot = w.value;
}

// "G61.1", "M6": the code as the tables write it, whatever the zeros of the source ("G040" = "G40").
std::string canonical(char letter, Code10 c) {
    std::string t = letter + std::to_string(c / 10);
    if (c % 10 != 0) t += "." + std::to_string(c % 10);
    return t;
}

bool in(Code10 c, std::initializer_list<Code10> set) {
    for (const Code10 s : set) {
        if (c == s) return true;
    }
    return false;
}

// Why a G code has no effect on this machine; nullptr if it is not one of those.
const char* ignored_g_reason(Code10 c) {
    if (c == 400) return "cutter compensation off: none is ever on";
    if (in(c, {410, 411, 420, 421})) return kNoToolTable;
    if (in(c, {430, 431, 432, 490})) return kNoToolTable;
    if (c == 800) return "canned cycle cancel: no canned cycle is ever active";
    if (c == 970) return "spindle RPM mode: the machine has no spindle speed control";
    return nullptr;
}

void ignore_code(BlockWords& b, const std::string& code, const char* reason) {
    b.ignored.push_back({code, reason});
    if (!b.ignored_code) b.ignored_code = code;
}

void g_word(BlockWords& b, const GcodeWord& w, Code10 c, const std::string& where, bool tools) {
    if (c <= 30 && c % 10 == 0) return set_once(b.motion, c, w, "motion (G0 G1 G2 G3)", where);
    if (in(c, {170, 180, 190})) return set_once(b.plane, c, w, "plane (G17 G18 G19)", where);
    if (in(c, {900, 910})) return set_once(b.distance, c, w, "distance mode (G90 G91)", where);
    if (in(c, {901, 911})) return set_once(b.arc_distance, c, w, "arc distance mode (G90.1 G91.1)", where);
    if (in(c, {200, 210})) return set_once(b.units, c, w, "units (G20 G21)", where);
    if (in(c, {930, 940})) return set_once(b.feed_mode, c, w, "feed mode (G93 G94)", where);
    if (in(c, {610, 611, 640})) return set_once(b.path_mode, c, w, "path control (G61 G61.1 G64)", where);
    if (in(c, {540, 550, 560, 570, 580, 590, 591, 592, 593})) {
        return set_once(b.coord_system, c, w, "coordinate system (G54 .. G59.3)", where);
    }
    if (in(c, {40, 100, 280, 281, 300, 301, 530, 920, 921, 922, 923})) {
        return set_once(b.non_modal, c, w, "non-modal (G4 G10 G28 G30 G53 G92)", where);
    }
    if (tools && in(c, {400, 410, 411, 420, 421})) {
        return set_once(b.cutter_comp, c, w, "cutter compensation (G40 G41 G41.1 G42 G42.1)", where);
    }
    if (tools && in(c, {430, 431, 432, 490})) {
        return set_once(b.tool_length, c, w, "tool length offset (G43 G43.1 G43.2 G49)", where);
    }
    if (const char* reason = ignored_g_reason(c)) return ignore_code(b, canonical('G', c), reason);
    b.unsupported.push_back(canonical('G', c));
}

void m_word(BlockWords& b, const GcodeWord& w, Code10 c, const std::string& where, bool tools) {
    if (in(c, {30, 40, 50})) return set_once(b.laser, c, w, "laser (M3 M4 M5)", where);
    if (in(c, {0, 10, 20, 300, 600})) return set_once(b.stop, c, w, "stop (M0 M1 M2 M30 M60)", where);
    if (tools && in(c, {60, 610})) return set_once(b.tool_change, c, w, "tool change (M6 M61)", where);
    const std::string text = canonical('M', c);
    if (c == 60) return ignore_code(b, text, "tool change: the machine has one tool");
    if (in(c, {70, 80, 90})) return ignore_code(b, text, "coolant: the machine has none");
    if (c >= 1000 && c <= 1990 && c % 10 == 0) {
        return ignore_code(b, text, "user-defined M code (M100-M199): nothing is attached to it");
    }
    b.unsupported.push_back(text);
}

}  // namespace

BlockWords group_words(const std::vector<GcodeWord>& words, const std::string& where, bool tool_table) {
    BlockWords b;
    for (const GcodeWord& w : words) {
        switch (w.letter) {
            case 'G':
            case 'M': {
                const std::optional<Code10> code = code_of(w);
                if (!code) {
                    b.unsupported.push_back(w.text);
                } else if (w.letter == 'G') {
                    g_word(b, w, *code, where, tool_table);
                } else {
                    m_word(b, w, *code, where, tool_table);
                }
                break;
            }
            case 'X':
                set_value(b.x, w, where);
                break;
            case 'Y':
                set_value(b.y, w, where);
                break;
            case 'Z':
                set_value(b.z, w, where);
                break;
            case 'A':
                set_value(b.a, w, where);
                break;
            case 'E':
                set_value(b.e, w, where);
                break;
            case 'I':
                set_value(b.i, w, where);
                break;
            case 'J':
                set_value(b.j, w, where);
                break;
            case 'R':
                set_value(b.r, w, where);
                break;
            case 'F':
                set_value(b.f, w, where);
                break;
            case 'P':
                set_value(b.p, w, where);
                break;
            case 'Q':
                set_value(b.q, w, where);
                break;
            case 'S':
                set_value(b.s, w, where);
                break;
            case 'L':
                set_value(b.l, w, where);
                break;
            case 'N':
                break;  // block number
            case 'T':
                if (tool_table) {
                    set_value(b.t, w, where);
                } else {
                    b.ignored.push_back({w.text, "tool select: the machine has one tool"});
                }
                break;
            case 'D':
                if (tool_table) {
                    set_value(b.d, w, where);
                } else {
                    b.ignored.push_back({w.text, kNoToolTable});
                }
                break;
            case 'H':
                if (tool_table) {
                    set_value(b.h, w, where);
                } else {
                    b.ignored.push_back({w.text, kNoToolTable});
                }
                break;
            case 'O':
                if (std::isnan(w.value)) {
                    b.unsupported.push_back(w.text);
                } else {
                    b.ignored.push_back({w.text, "program number"});
                }
                break;
            case kParameterWord:
                b.unsupported.push_back("#");
                break;  // parameters
            case kExpressionWord:
                b.unsupported.push_back("[...]");
                break;  // expressions
            default:
                b.unsupported.push_back(w.text);
        }
    }
    return b;
}

}  // namespace cnc::host
