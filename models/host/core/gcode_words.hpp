// The words of one G-code block sorted into RS274/NGC modal groups, each G and M code classified as executed,
// ignored by this machine (with the reason) or unsupported. At most one word per group and per letter.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "host/core/gcode_lexer.hpp"

namespace cnc::host {

// G and M codes with one decimal are kept as tenths: G61.1 = 611, G59.3 = 593, G92.1 = 921, G4 = 40.
using Code10 = int;

struct IgnoredUse {
    std::string word;
    std::string reason;
};

struct BlockWords {
    std::optional<Code10> motion;        // G0 G1 G2 G3
    std::optional<Code10> plane;         // G17 G18 G19
    std::optional<Code10> distance;      // G90 G91
    std::optional<Code10> arc_distance;  // G90.1 G91.1
    std::optional<Code10> units;         // G20 G21
    std::optional<Code10> feed_mode;     // G93 G94
    std::optional<Code10> path_mode;     // G61 G61.1 G64
    std::optional<Code10> coord_system;  // G54 .. G59.3
    std::optional<Code10> non_modal;     // G4 G10 G28 G28.1 G30 G30.1 G53 G92 G92.1 G92.2 G92.3
    std::optional<Code10> laser;         // M3 M4 M5
    std::optional<Code10> stop;          // M0 M1 M60 (pause), M2 M30 (end)
    // With a tool table only (else these codes and T D H are ignored words):
    std::optional<Code10> cutter_comp;  // G40 G41 G41.1 G42 G42.1
    std::optional<Code10> tool_length;  // G43 G43.1 G43.2 G49
    std::optional<Code10> tool_change;  // M6 M61
    std::optional<double> t, d, h;
    std::optional<double> x, y, z, a, e, i, j, r, f, p, q, s, l;
    std::vector<IgnoredUse> ignored;
    std::optional<std::string> ignored_code;  // the first ignored G or M code: RS274/NGC lets it take P and Q
    std::vector<std::string> unsupported;     // word texts
};

// BadInput(where, ...) for two words of one modal group, a letter given twice or a G/M number that is not a
// code (negative, more than one decimal). Unknown codes and letters go to `unsupported`, not to an exception.
// tool_table: the machine has a tool table (`scenario.tool_table`), so T, D, H, M6, M61 and G40-G43/G49 are
// executed; without one they are ignored words (M61 unsupported), as a machine with one tool ignores them.
BlockWords group_words(const std::vector<GcodeWord>& words, const std::string& where, bool tool_table = false);

}  // namespace cnc::host
