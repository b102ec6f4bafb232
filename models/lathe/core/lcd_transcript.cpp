#include "lathe/core/lcd_transcript.hpp"

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace cnc::lathe {

void LcdTranscript::changed(double t_s, const LcdLines& lines) {
    tick(t_s);
    m_pending = {t_s, lines};
    m_has_pending = true;
}

void LcdTranscript::tick(double t_s) {
    if (!m_has_pending || t_s - m_pending.t_s < kLcdSettleS) return;
    m_has_pending = false;
    if (!m_screens.empty() && m_screens.back().lines == m_pending.lines) return;  // back to what was read
    m_screens.push_back(m_pending);
}

const std::vector<LcdScreen>& LcdTranscript::screens(double end_s) {
    tick(end_s);
    return m_screens;
}

namespace {

std::string seconds_text(double t_s) {
    std::ostringstream out;
    out << std::fixed << std::setprecision(3) << t_s;
    return out.str();
}

}  // namespace

std::string transcript_text(const std::vector<LcdScreen>& screens) {
    std::size_t width = 0;
    for (const LcdScreen& screen : screens) width = std::max(width, seconds_text(screen.t_s).size());
    std::ostringstream out;
    for (const LcdScreen& screen : screens) {
        out << "  " << std::setw(static_cast<int>(width)) << seconds_text(screen.t_s) << " s  |" << screen.lines[0]
            << "|" << screen.lines[1] << "|\n";
    }
    return out.str();
}

}  // namespace cnc::lathe
