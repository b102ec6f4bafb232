#include "run/progress.hpp"

#include <fmt/format.h>

namespace cnc::sim {

namespace {

constexpr double kQuietWallS = 1.0;          // runs shorter than this show nothing
constexpr double kRedrawWallS = 0.25;        // terminal line: four redraws a second are enough to read
constexpr double kTenthsPerEstimate = 10.0;  // log: one line per 10 % of the estimate

}  // namespace

Progress::Progress(std::ostream& out, ProgressStyle style, double expected_s, std::string label)
    : m_out(out),
      m_style(expected_s > 0.0 ? style : ProgressStyle::Off),  // an empty job has nothing to show a share of
      m_expected_s(expected_s),
      m_label(std::move(label)) {}

std::string Progress::prefix() const {
    return "cncsim: " + (m_label.empty() ? "" : m_label + ": ");
}

std::string Progress::text(double sim_s, double wall_s) const {
    const double fraction = sim_s / m_expected_s;
    std::string t = prefix() + fmt::format(FMT_STRING("simulated {:.1f} s of ~{:.1f} s"), sim_s, m_expected_s);
    if (fraction >= 1.0) return t + fmt::format(FMT_STRING(" (past the estimate), {:.1f} s wall"), wall_s);
    t += fmt::format(FMT_STRING(" ({:.0f} %), {:.1f} s wall"), 100.0 * fraction, wall_s);
    if (sim_s > 0.0) t += fmt::format(FMT_STRING(", about {:.0f} s to go"), wall_s * (m_expected_s - sim_s) / sim_s);
    return t;
}

void Progress::show(const std::string& text) {
    if (m_style == ProgressStyle::Terminal) {
        // Blank out what is left of a longer previous line.
        const std::size_t pad = m_last_width > text.size() ? m_last_width - text.size() : 0;
        m_out << '\r' << text << std::string(pad, ' ') << std::flush;
        m_last_width = text.size();
    } else {
        m_out << text << '\n' << std::flush;
    }
    m_shown = true;
}

void Progress::update(double sim_s, double wall_s) {
    if (m_style == ProgressStyle::Off || wall_s < kQuietWallS) return;
    if (m_style == ProgressStyle::Terminal) {
        if (m_shown && wall_s - m_last_draw_wall_s < kRedrawWallS) return;
        m_last_draw_wall_s = wall_s;
        show(text(sim_s, wall_s));
        return;
    }
    const double tenths = kTenthsPerEstimate * sim_s / m_expected_s;
    if (tenths < m_next_tenths) return;
    show(text(sim_s, wall_s));
    while (m_next_tenths <= tenths) {
        m_next_tenths = m_next_tenths < kTenthsPerEstimate ? m_next_tenths + 1.0 : 2.0 * m_next_tenths;
    }
}

void Progress::finish(double sim_s, double wall_s) {
    if (!m_shown) return;
    const std::string done = prefix() + fmt::format(FMT_STRING("simulated {:.1f} s in {:.1f} s wall"), sim_s, wall_s);
    if (m_style == ProgressStyle::Terminal) {
        show(done);
        m_out << '\n' << std::flush;
    } else {
        show(done);
    }
}

}  // namespace cnc::sim
