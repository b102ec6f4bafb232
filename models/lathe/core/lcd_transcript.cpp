#include "lathe/core/lcd_transcript.hpp"

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

}  // namespace cnc::lathe
