// What a person reading seed 002's LCD sees: the display's contents each time they settle, with the time they
// appeared. The firmware writes a prompt character by character (a clear and 16 characters take well under
// 1 ms with the controller always ready); contents that stay less than kLcdSettleS are not a screen anyone
// reads, and the liquid crystal itself needs tens of ms to switch (typical TN response, 20 to 50 ms), so they
// are left out.
#pragma once
#include <string>
#include <vector>

#include "lathe/core/hd44780.hpp"

namespace cnc::lathe {

inline constexpr double kLcdSettleS = 0.05;

struct LcdScreen {
    double t_s = 0.0;  // when these contents were complete (the last change)
    LcdLines lines;
};

// One line per screen, "  <time> s  |<line 1>|<line 2>|", the times (s, to the ms) right-aligned to the widest,
// so that the screens stay in one column past 10 s and 100 s.
[[nodiscard]] std::string transcript_text(const std::vector<LcdScreen>& screens);

class LcdTranscript {
public:
    // The display changed to `lines` at t_s (times never decrease).
    void changed(double t_s, const LcdLines& lines);
    // The time is now t_s: contents unchanged for kLcdSettleS join the transcript.
    void tick(double t_s);
    // The end of the run: what shows then is kept if it has stayed kLcdSettleS.
    [[nodiscard]] const std::vector<LcdScreen>& screens(double end_s);

private:
    std::vector<LcdScreen> m_screens;
    LcdScreen m_pending;
    bool m_has_pending = false;
};

}  // namespace cnc::lathe
